#include "app/reconstruct_command.h"

#include <algorithm>
#include <filesystem>

#include "image/image_io.h"
#include "render/gradient_images.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {

int reconstruct_command(const std::string& in_exr, const std::string& out_path,
                        const ReconSettings& settings, Context& ctx, Stats* stats) {
  Image in = read_image(in_exr);
  Image out = gradient_image(ctx, gradient_layers_from(in, in_exr), settings, stats);
  log::info("reconstructed ", in_exr, " (", settings.norm == ReconNorm::L1 ? "L1" : "L2", ", alpha ",
            settings.alpha, ")");
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
