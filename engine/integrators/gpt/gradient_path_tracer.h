// Gradient-domain path tracing (`gpt`, Kettunen et al. 2015): per pixel sample a base path and
// four offset paths through the neighbouring pixels, traced in one wavefront; the shifts, their
// Jacobians and the MIS weights run in kernels (kernels/gpt over kernels/shift, kernels/gradient
// and kernels/path). Produces the primal image, the forward-difference gradients dx and dy, and
// the directly seen emission (kept out of the gradients), then reconstructs the image.
//
// Parameters (IntegratorParams):
//   shift            hybrid (default: reconnection where rough, half-vector copy elsewhere) | replay |
//                    manifold (hybrid, and a manifold walk where the base runs from a rough vertex
//                    through specular vertices to the next rough vertex, so that such offsets
//                    rejoin the base; render/manifold_walks.h has the walk's settings)
//   shift_threshold  roughness at or below which a vertex is glossy, not reconnected (0.001)
//   aux              true: also write the first hits' albedo, normal and depth layers
//   direct_samples   extra camera rays a pass for the emission seen directly (8), for each pixel
//                    an emitter's edge crosses (integrators/gpt/direct_samples.h): the direct
//                    layer, which the gradients leave out, at a primary ray a sample
//   batches          1 or 2 batches of groups a chunk, stepped in turn for host/device overlap
//                    (default: 2 on a GPU, 1 on a CPU device; GptSettings::batches)
//   recon, recon_solver, alpha: the reconstruction (render/gradient_images.h)
#pragma once
#include <optional>

#include "integrators/gpt/gradient_groups.h"
#include "render/aux_layers.h"
#include "render/gradient_film.h"
#include "render/gradient_images.h"
#include "render/integrator.h"
#include "integrators/gpt/direct_samples.h"

namespace gdr {

extern const std::vector<std::string> kGptParams;
GptSettings gpt_settings(const IntegratorParams& params);

class GradientPathTracer : public Integrator {
 public:
  GradientPathTracer(const RenderInputs& inputs, const GptSettings& gpt, const IntegratorParams& params = {});

  // The gradient layers alone, not reconstructed.
  GradientImages render_gradients(const RenderSettings& settings);
  RenderResult render(const RenderSettings& settings) override;

 protected:
  // `kind`: the groups of the gradient-domain bidirectional integrators (GradientGroups).
  GradientPathTracer(const RenderInputs& inputs, const GptSettings& gpt, const IntegratorParams& params,
                     GroupKind kind);
  // The groups of pixels [first, first + count) in pass `sample`, their sums into groups_.acc().
  virtual void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);
  // After a pass's chunks, before its sums are gathered into the film.
  virtual void end_pass() {}
  AuxLayers* aux() { return aux_ ? &*aux_ : nullptr; }

  RenderInputs in_;
  GradientGroups groups_;    // acc: a pixel's groups' sums at the pixel (the gather reads neighbours)

 private:
  IntegratorParams params_;  // the reconstruction's
  Kernel gather_;
  GradientFilm film_;
  std::optional<AuxLayers> aux_;
  DirectSamples direct_;  // --direct-samples
};

}  // namespace gdr
