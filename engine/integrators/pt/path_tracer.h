// The wavefront path tracer (`pt`): the unbiased reference every other integrator is measured
// against. Kernels generate and shade; Embree intersects the queues on the host in between.
// A chunk's paths may be split into batches, each with its queues, counters and command queue,
// stepped in turn: while the host waits for one batch's counters and traces its rays, the device
// shades the other (host/device overlap). The images do not depend on the split.
//
// Parameters (IntegratorParams):
//   strategy  mis (default: BSDF and light sampling by the power heuristic) | bsdf | light
//   aux       true: also write the first hits' albedo, normal and depth layers
//   batches   1 or 2 batches a chunk (default 2; 1 where a chunk has too few paths to split;
//             scripts/bench-pt --batches 1,2 measures both)
//   lanes     8: camera rays are generated and the diffuse and smooth plastic queues shaded
//             eight paths a work item (pt_generate_lanes, pt_shade_lanes_<material>: written for
//             CPU devices, whose compiler widens no kernel of these across work items); 1: one
//             path a work item (default: 8 on CPU devices, 1 on GPUs)
#pragma once
#include <deque>
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
  int batches = 2;  // a chunk's batches (1 where a chunk has too few paths to split)
  std::optional<int> lanes;  // 1 or 8 (default: the device's)
};
extern const std::vector<std::string> kPtParams;
PtSettings pt_settings(const IntegratorParams& params);

class PathTracer : public Integrator {
 public:
  PathTracer(const RenderInputs& inputs, const PtSettings& settings);

  RenderResult render(const RenderSettings& settings) override;

  // The stages of one chunk on its first batch (the whole chunk with one batch), in the order
  // trace_chunk runs them; public so that the kernel benchmarks time exactly what a render runs.
  // Queue `cur` is read, queue 1 - cur written.
  GdrPtParams params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const;
  void generate(const GdrPtParams& params) { generate(batches_[0], params); }  // camera rays into queue 0
  void intersect(int cur, cl_uint active, bool camera) { intersect(batches_[0], cur, active, camera); }
  // Routes the hits to the material queues and shades each (PT_COUNTER_*).
  const std::vector<cl_uint>& shade(const GdrPtParams& params, int cur, cl_uint active);
  void occlude(cl_uint shadows) { occlude(batches_[0], shadows); }
  void add_shadows(cl_uint shadows) { add_shadows(batches_[0], shadows); }
  Buffer<GdrRayHit>& rays(int cur) { return batches_[0].queues.rays[cur]; }
  Buffer<cl_uint>& queue(int cur) { return batches_[0].queues.slots[cur]; }
  Buffer<GdrPathState>& paths() { return batches_[0].paths; }
  Buffer<GdrRay>& shadow_rays() { return batches_[0].shadow_rays; }

 private:
  // A part of a chunk's paths in flight: its queues, states and counters, its command queue, and
  // where it stands: `active` paths in queue `cur` at `depth`, their shading queued (`shading`).
  struct Batch {
    Batch(const RenderInputs& in, const KernelFactory& kernels, size_t capacity, int command_queue,
          const MaterialQueues::LaneKernels& lanes);
    int command_queue;
    RayQueues queues;
    Buffer<GdrPathState> paths;
    Buffer<GdrRay> shadow_rays;
    Buffer<Vec4> shadow_values;
    DeviceCounters counters;
    MaterialQueues materials;
    GdrPtParams params{};
    cl_uint active = 0;
    int cur = 0, depth = 0;
    bool shading = false;
  };

  void generate(Batch& b, const GdrPtParams& params);
  void intersect(Batch& b, int cur, cl_uint active, bool camera);
  void enqueue_shade(Batch& b, const GdrPtParams& params, int cur, cl_uint active);
  void occlude(Batch& b, cl_uint shadows);
  void add_shadows(Batch& b, cl_uint shadows);
  // One step of batch b: its last shading's shadows, then its next bounce traced and its shading
  // queued (the host waits only for b's commands).
  void step(Batch& b);
  // Traces one sample for pixels [first, first + count) and adds the radiance into the film.
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);

  RenderInputs in_;
  PtSettings pt_;
  KernelFactory kernels_;
  int lanes_;  // 1, or 8: the camera rays and the diffuse queue eight paths a work item
  Kernel generate_, route_, shadow_;
  size_t capacity_;  // paths in flight at once, over all batches
  Film film_;
  std::deque<Batch> batches_;
  std::optional<AuxLayers> aux_;
};

}  // namespace gdr
