// The wavefront path tracer (`pt`): the unbiased reference every other integrator is measured
// against. Kernels generate and shade; Embree intersects the queues on the host in between.
//
// Parameters (IntegratorParams):
//   strategy  mis (default: BSDF and light sampling by the power heuristic) | bsdf | light
//   aux       true: also write the first hits' albedo, normal and depth layers
#pragma once
#include <optional>

#include "render/aux_layers.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/material_queues.h"
#include "render/wavefront/ray_queues.h"
#include "shared/pt_types.h"

namespace gdr {

struct PtSettings {
  int strategy = PT_STRATEGY_MIS;  // PT_STRATEGY_*
  bool aux = false;
};
extern const std::vector<std::string> kPtParams;
PtSettings pt_settings(const IntegratorParams& params);

class PathTracer : public Integrator {
 public:
  PathTracer(const RenderInputs& inputs, const PtSettings& settings);

  RenderResult render(const RenderSettings& settings) override;

  // The stages of one chunk, in the order trace_chunk runs them; public so that the kernel
  // benchmarks time exactly what a render runs. Queue `cur` is read, queue 1 - cur written.
  GdrPtParams params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const;
  void generate(const GdrPtParams& params);  // camera rays into queue 0
  void intersect(int cur, cl_uint active, bool camera);
  // Routes the hits to the material queues and shades each (PT_COUNTER_*).
  const std::vector<cl_uint>& shade(const GdrPtParams& params, int cur, cl_uint active);
  void occlude(cl_uint shadows);
  void add_shadows(cl_uint shadows);
  Buffer<GdrRayHit>& rays(int cur) { return queues_.rays[cur]; }
  Buffer<cl_uint>& queue(int cur) { return queues_.slots[cur]; }
  Buffer<GdrPathState>& paths() { return paths_; }
  Buffer<GdrRay>& shadow_rays() { return shadow_rays_; }

 private:
  // Traces one sample for pixels [first, first + count) and adds the radiance into the film.
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);

  RenderInputs in_;
  PtSettings pt_;
  KernelFactory kernels_;
  Kernel generate_, route_, shadow_;
  size_t capacity_;  // paths in flight at once
  RayQueues queues_;
  Buffer<GdrPathState> paths_;
  Buffer<GdrRay> shadow_rays_;
  Buffer<Vec4> shadow_values_;
  DeviceCounters counters_;
  Film film_;
  MaterialQueues materials_;
  std::optional<AuxLayers> aux_;
};

}  // namespace gdr
