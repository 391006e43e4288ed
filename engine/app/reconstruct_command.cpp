#include "app/reconstruct_command.h"

#include "app/output_paths.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "render/gradient_images.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {

int reconstruct_command(const std::string& in_exr, const std::string& out_path,
                        const ReconSettings& settings, Context& ctx, Stats* stats) {
  Image in = read_image(in_exr);
  Image out = gradient_image(ctx, gradient_layers_from(in, in_exr, settings.norm == ReconNorm::Weighted), settings,
                             stats);
  log::info("reconstructed ", in_exr, " (", recon_norm_name(settings.norm), ", alpha ",
            settings.alpha, ")");
  ImageOutputs images = image_outputs(out_path);
  OutputSet outputs;
  add_image_outputs(outputs, images, out);
  outputs.commit();
  return 0;
}

}  // namespace gdr
