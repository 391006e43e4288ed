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
//   recon, recon_solver, alpha: the reconstruction (render/gradient_images.h)
#pragma once
#include <optional>

#include "render/aux_layers.h"
#include "render/gradient_film.h"
#include "render/gradient_images.h"
#include "render/integrator.h"
#include "render/manifold_walks.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/ray_queues.h"
#include "shared/gpt_types.h"

namespace gdr {

struct GptSettings {
  int shift = GPT_SHIFT_HYBRID;  // GPT_SHIFT_*
  float shift_threshold = GDR_GLOSSY_THRESHOLD;
  bool aux = false;
  ManifoldSettings manifold;
};
extern const std::vector<std::string> kGptParams;
GptSettings gpt_settings(const IntegratorParams& params);

class GradientPathTracer : public Integrator {
 public:
  GradientPathTracer(const RenderInputs& inputs, const GptSettings& gpt, const IntegratorParams& params = {});

  // The gradient layers alone, not reconstructed.
  GradientImages render_gradients(const RenderSettings& settings);
  RenderResult render(const RenderSettings& settings) override;

 private:
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);
  GdrGptParams params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const;
  // Offset rays' hits and reconnection segments' visibility, filed into the offsets' states.
  void intersect_offsets(cl_uint rays, cl_uint reconnects);
  // Solves the walks the shift step queued and joins their offsets to the base.
  void walk_offsets(const GdrGptParams& p, cl_uint walks);

  RenderInputs in_;
  GptSettings gpt_;
  IntegratorParams params_;  // the reconstruction's
  KernelFactory kernels_;
  Kernel generate_, scatter_, shade_, shadow_, shift_, gather_;
  size_t capacity_;  // groups in flight at once
  RayQueues base_queues_;
  Buffer<GdrRayHit> offset_rays_;
  Buffer<GdrRay> reconnect_rays_;
  Buffer<GdrRay> shadow_rays_;
  Buffer<GptBaseState> bases_;
  Buffer<GptOffsetState> offsets_;
  Buffer<Vec4> acc_;   // GPT_ACC_COUNT per pixel of the whole image (gather reads neighbours)
  Buffer<Vec4> pend_;  // GPT_PEND_COUNT per group
  DeviceCounters counters_;
  GradientFilm film_;
  std::optional<AuxLayers> aux_;
  // The manifold shift, where the scene has specular chains (else --shift manifold is hybrid).
  Buffer<GptChain> chains_;
  Buffer<GdrManifoldWalk> walks_;
  Buffer<GdrManifoldResult> walk_results_;
  std::optional<ManifoldWalks> manifold_;
  std::optional<Kernel> join_;
};

// Whether --shift manifold walks in this scene (it has specular chains).
bool gpt_manifold_enabled(const Scene& scene, const GptSettings& gpt);

}  // namespace gdr
