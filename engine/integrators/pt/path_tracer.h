// The wavefront path tracer (`pt`): the unbiased reference every other integrator is measured
// against. Kernels generate and shade; Embree intersects the queues on the host in between.
#pragma once
#include <memory>

#include "accel/embree_scene.h"
#include "device/context.h"
#include "integrators/device_scene.h"
#include "integrators/render_settings.h"
#include "scene/scene.h"
#include "shared/pt_types.h"
#include "shared/ray_types.h"

namespace gdr {

class PathTracer {
 public:
  PathTracer(Context& context, const Scene& scene, EmbreeScene& embree);

  RenderResult render(const RenderSettings& settings);

  // The stages of one chunk, in the order trace_chunk runs them; public so that the kernel
  // benchmarks time exactly what a render runs. Queue `cur` is read, queue 1 - cur written.
  GdrPtParams params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const {
    return device_scene_.path_params(settings, sample, first, count);
  }
  void generate(const GdrPtParams& params);  // camera rays into queue 0
  void intersect(int cur, cl_uint active, bool camera);
  std::vector<cl_uint> shade(const GdrPtParams& params, int cur, cl_uint active);  // PT_COUNTER_*
  void occlude(cl_uint shadows);
  void add_shadows(cl_uint shadows);
  Buffer<GdrRayHit>& rays(int cur) { return rays_[cur]; }
  Buffer<cl_uint>& queue(int cur) { return queue_[cur]; }
  Buffer<GdrPathState>& paths() { return paths_; }
  Buffer<GdrRay>& shadow_rays() { return shadow_rays_; }

 private:
  // Traces one sample for pixels [first, first + count) and adds the radiance into film_.
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);

  Context& ctx_;
  const Scene& scene_;
  EmbreeScene& embree_;
  DeviceScene device_scene_;
  Kernel generate_, shade_, shadow_;
  size_t capacity_;  // paths in flight at once
  Buffer<GdrRayHit> rays_[2];
  Buffer<cl_uint> queue_[2];
  Buffer<GdrPathState> paths_;
  Buffer<GdrRay> shadow_rays_;
  Buffer<Vec4> shadow_values_;
  Buffer<cl_uint> counters_;
  Buffer<Vec4> film_;
  // Auxiliary layers (RenderSettings::aux): first-hit albedo, normal and depth sums.
  Kernel aux_;
  Buffer<Vec4> aux_albedo_, aux_normal_;
  Buffer<float> aux_depth_;
};

}  // namespace gdr
