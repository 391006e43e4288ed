// The output of a gradient-domain render: R,G,B is the screened-Poisson reconstruction of
// (primal - direct) from the gradients, plus the directly seen emission that the gradients leave
// out; the layers primal, dx, dy, direct and variance are kept beside it.
#pragma once
#include <optional>
#include <string>

#include "device/context.h"
#include "image/image.h"
#include "recon/reconstruct.h"
#include "render/integrator_params.h"
#include "render/render_settings.h"

namespace gdr {

// The layers of a gradient-domain render, each interleaved RGB, means over the samples taken.
struct GradientImages {
  int width = 0, height = 0;
  int samples = 0;
  double seconds = 0;
  std::vector<float> primal, dx, dy, direct;
  std::vector<float> variance;  // per-pixel variance of the primal's mean
};

// The parameters every gradient integrator reads: recon (l1 | l2 | none), recon_solver (fast |
// cg), alpha. Without `recon`, L1 with the fast solver and alpha 0.2.
extern const std::vector<std::string> kReconParams;
std::optional<ReconSettings> recon_from_params(const IntegratorParams& params);

// R,G,B reconstructed with `recon`, or the primal without it.
Image gradient_image(Context& ctx, const GradientImages& layers,
                     const std::optional<ReconSettings>& recon, Stats* stats);

// The render's result: the image above, reconstructed as `params` say (timed as recon/total).
RenderResult gradient_result(Context& ctx, const GradientImages& layers, const IntegratorParams& params,
                             Stats* stats);

// The layers of a saved render (primal, dx, dy required; direct and variance optional).
// Throws InputError naming `path` and the missing layer.
GradientImages gradient_layers_from(const Image& image, const std::string& path);

}  // namespace gdr
