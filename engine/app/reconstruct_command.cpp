#include "app/reconstruct_command.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "image/image_io.h"
#include "recon/reconstruct.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {
namespace {

ReconNorm parse_norm(const std::string& recon) {
  std::string s = recon;
  std::transform(s.begin(), s.end(), s.begin(), ::tolower);
  if (s == "l1") return ReconNorm::L1;
  if (s == "l2") return ReconNorm::L2;
  throw Error("unknown reconstruction '" + recon + "' (expected l1 or l2)");
}

}  // namespace

int reconstruct_command(const std::string& in_exr, const std::string& out_path,
                        const std::string& recon, float alpha, Context& ctx, Stats* stats) {
  ReconSettings settings;
  settings.norm = parse_norm(recon);
  if (!std::isfinite(alpha) || alpha < 0) {
    throw Error("reconstruction alpha must be a finite value >= 0, got " + std::to_string(alpha));
  }
  settings.alpha = alpha;

  Image in = read_image(in_exr);
  for (const char* layer : {"primal", "dx", "dy"}) {
    if (!in.has_rgb_layer(layer)) {
      std::string l(layer);
      throw InputError(in_exr, 0, "missing layer '" + l + "' (needs channels " + l + ".R, " + l +
                                      ".G and " + l + ".B)");
    }
  }
  std::vector<float> primal = in.rgb_layer("primal"), dx = in.rgb_layer("dx"), dy = in.rgb_layer("dy");
  ReconResult r = reconstruct(ctx, in.width, in.height, primal, dx, dy, settings, stats);
  log::info("reconstructed ", in_exr, " (", recon, ", alpha ", alpha, "): ", r.iterations,
            " iterations, residual ", r.residual, ", ", r.seconds, " s");

  Image out(in.width, in.height, {});
  out.add_rgb_layer("", r.rgb);
  out.add_rgb_layer("primal", primal);
  out.add_rgb_layer("dx", dx);
  out.add_rgb_layer("dy", dy);
  std::filesystem::path exr_path(out_path), png_path(out_path);
  std::string ext = exr_path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  if (ext == ".png") exr_path.replace_extension(".exr");
  png_path.replace_extension(".png");
  write_exr(exr_path.string(), out);
  write_png(png_path.string(), out);
  return 0;
}

}  // namespace gdr
