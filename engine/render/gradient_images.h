// The output of a gradient-domain render: R,G,B is the screened-Poisson reconstruction of
// (primal - direct) from the gradients, plus the directly seen emission that the gradients leave
// out; the layers primal, dx, dy, direct and the per-pixel variance estimates primal_variance,
// dx_variance and dy_variance are kept beside it, and with the weighted reconstruction the same
// layers of the even and of the odd passes (even.primal, odd.dx_variance, ...), so that a saved
// render can be reconstructed again.
//
// The weighted reconstruction weights each half of the passes by the variance estimates of the
// other half and averages the two results. Weights from the data's own estimates are low exactly
// where the data came out high (a rare bright path raises both a pixel's value and its variance
// estimate), which darkens the image where such paths carry the light; weights from independent
// passes are independent of the values they weight, and a linear solve with weights independent
// of its unbiased, consistent inputs stays unbiased.
#pragma once
#include <optional>
#include <string>

#include "device/context.h"
#include "image/image.h"
#include "recon/reconstruct.h"
#include "render/integrator_params.h"
#include "render/render_settings.h"

namespace gdr {

// The means of one set of passes, each interleaved RGB, and the per-pixel variance estimates of
// primal, dx and dy (render/film.h: PassEstimate); empty when unknown.
struct GradientLayers {
  std::vector<float> primal, dx, dy, direct;
  std::vector<float> primal_variance, dx_variance, dy_variance;
};

// The layers of a gradient-domain render over all its samples, and those of its even and its
// odd passes apart (empty where a half has no passes or a saved render does not hold them).
struct GradientImages : GradientLayers {
  int width = 0, height = 0;
  int samples = 0;
  double seconds = 0;
  GradientLayers halves[2];
};

// The parameters every gradient integrator reads: recon (l1 | l2 | weighted | none),
// recon_solver (fast | cg), alpha. Without `recon`, the weighted form (the convergence study's
// choice: as low an error as L1 on the scenes measured, without L1's loss of rare bright light)
// with the fast solver and alpha 1 (0.2 for L1 and L2).
extern const std::vector<std::string> kReconParams;
std::optional<ReconSettings> recon_from_params(const IntegratorParams& params);

// R,G,B reconstructed with `recon`, or the primal without it.
Image gradient_image(Context& ctx, const GradientImages& layers,
                     const std::optional<ReconSettings>& recon, Stats* stats);

// The render's result: the image above, reconstructed as `params` say (timed as recon/total).
RenderResult gradient_result(Context& ctx, const GradientImages& layers, const IntegratorParams& params,
                             Stats* stats);

// The layers of a saved render (primal, dx, dy required; direct, the variances and the halves
// optional; a layer named `variance` is the primal's, as older renders saved it). With
// halves_required (the weighted reconstruction) both halves' layers must be there. Throws
// InputError naming `path` and the missing layer.
GradientImages gradient_layers_from(const Image& image, const std::string& path, bool halves_required = false);

}  // namespace gdr
