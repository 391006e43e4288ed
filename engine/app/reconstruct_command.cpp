#include "app/reconstruct_command.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "image/image_io.h"
#include "integrators/gpt/gradient_image.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {
namespace {

std::string parse_norm(const std::string& recon) {
  std::string s = recon;
  std::transform(s.begin(), s.end(), s.begin(), ::tolower);
  if (s == "l1" || s == "l2") return s;
  throw Error("unknown reconstruction '" + recon + "' (expected l1 or l2)");
}

}  // namespace

int reconstruct_command(const std::string& in_exr, const std::string& out_path,
                        const std::string& recon, float alpha, Context& ctx, Stats* stats) {
  std::string norm = parse_norm(recon);
  if (!std::isfinite(alpha) || alpha < 0) {
    throw Error("reconstruction alpha must be a finite value >= 0, got " + std::to_string(alpha));
  }

  Image in = read_image(in_exr);
  Image out = gradient_image(ctx, gradient_layers_from(in, in_exr), norm, alpha, stats);
  log::info("reconstructed ", in_exr, " (", recon, ", alpha ", alpha, ")");
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
