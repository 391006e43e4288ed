// Gradient-domain path tracing (`gpt`, Kettunen et al. 2015): per pixel sample a base path and
// four offset paths through the neighbouring pixels, traced in one wavefront; the shifts, their
// Jacobians and the MIS weights run in kernels/gpt/. Produces the primal image, the forward-
// difference gradients dx and dy, and the directly seen emission (kept out of the gradients).
#pragma once
#include "accel/embree_scene.h"
#include "device/context.h"
#include "integrators/device_scene.h"
#include "integrators/render_settings.h"
#include "scene/scene.h"
#include "shared/gpt_types.h"
#include "shared/ray_types.h"

namespace gdr {

struct GptSettings {
  int shift = GPT_SHIFT_HYBRID;  // GPT_SHIFT_*
  float shift_threshold = 0.001f;
};

// The layers of a gradient-domain render, each interleaved RGB, means over the samples taken.
struct GradientImages {
  int width = 0, height = 0;
  int samples = 0;
  double seconds = 0;
  std::vector<float> primal, dx, dy, direct;
  std::vector<float> variance;  // per-pixel variance of the primal's mean
};

class GradientPathTracer {
 public:
  GradientPathTracer(Context& context, const Scene& scene, EmbreeScene& embree, const GptSettings& gpt);

  GradientImages render(const RenderSettings& settings);

 private:
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);
  GdrGptParams params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const;

  Context& ctx_;
  const Scene& scene_;
  EmbreeScene& embree_;
  GptSettings gpt_;
  DeviceScene device_scene_;
  Kernel generate_, scatter_, shade_, shadow_, shift_, gather_;
  size_t capacity_;  // groups in flight at once
  Buffer<GdrRayHit> base_rays_[2];
  Buffer<GdrRayHit> offset_rays_;
  Buffer<GdrRay> reconnect_rays_;
  Buffer<GdrRay> shadow_rays_;
  Buffer<GptBaseState> bases_;
  Buffer<GptOffsetState> offsets_;
  Buffer<Vec4> acc_;   // GPT_ACC_COUNT per pixel of the whole image (gather reads neighbours)
  Buffer<Vec4> pend_;  // GPT_PEND_COUNT per group
  Buffer<cl_uint> counters_;
  Buffer<Vec4> primal_, dx_, dy_, direct_, primal_sq_;
};

}  // namespace gdr
