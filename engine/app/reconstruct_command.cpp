#include "app/reconstruct_command.h"

#include "app/output_paths.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "render/gradient_images.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {
namespace {

int reconstruct_image(const Image& in, const std::string& in_exr, const std::string& out_path,
                      const std::optional<ReconSettings>& settings, Context& ctx, Stats* stats) {
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

}  // namespace

int reconstruct_command(const std::string& in_exr, const std::string& out_path,
                        const std::optional<ReconSettings>& settings, Context& ctx, Stats* stats) {
  return reconstruct_image(read_image(in_exr), in_exr, out_path, settings, ctx, stats);
}

int reconstruct_command(const std::string& in_exr, const std::string& out_path, const IntegratorParams& params,
                        Context& ctx, Stats* stats) {
  Image in = read_image(in_exr);
  IntegratorParams p = params;
  // The default form, weighted, needs the halves that only a weighted render saves; a render
  // saved with another reconstruction is reconstructed by L1 unless --recon says otherwise.
  if (!p.has("recon") && !in.has_rgb_layer("even.primal")) {
    p.set("recon", "l1");
    log::info(in_exr, " holds no even/odd halves for the weighted reconstruction: using l1");
  }
  return reconstruct_image(in, in_exr, out_path, recon_from_params(p), ctx, stats);
}

}  // namespace gdr
