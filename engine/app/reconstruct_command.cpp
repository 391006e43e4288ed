#include "app/reconstruct_command.h"

#include "app/output_paths.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "render/gradient_images.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {

int reconstruct_command(const std::string& in_exr, const std::string& out_path,
                        const std::optional<ReconSettings>& settings, Context& ctx, Stats* stats) {
  Image in = read_image(in_exr);
  const bool weighted = settings && settings->norm == ReconNorm::Weighted;
  Image out = gradient_image(ctx, gradient_layers_from(in, in_exr, weighted), settings, stats);
  if (settings) {
    log::info("reconstructed ", in_exr, " (", recon_norm_name(settings->norm), ", alpha ", settings->alpha, ")");
  } else {
    log::info("wrote the primal of ", in_exr, " (no reconstruction)");
  }
  ImageOutputs images = image_outputs(out_path);
  OutputSet outputs;
  add_image_outputs(outputs, images, out);
  outputs.commit();
  return 0;
}

}  // namespace gdr
