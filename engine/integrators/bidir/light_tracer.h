// The light tracer (`lt`): light subpaths traced from the lights in wavefront batches (emission
// sampling, importance transport), each vertex connected to the camera through a shadow ray and
// splatted into the film (render/splat_film.h, gathered deterministically). Emission the camera
// sees directly (an area light or the environment behind a pixel) is what a light subpath cannot
// reach through the pinhole: one camera ray per pixel and pass adds it, as Mitsuba's ptracer
// does with hide_emitters = false. A pass traces one light subpath per pixel.
//
// Parameters (IntegratorParams):
//   aux   true: also write the camera rays' first hits' albedo, normal and depth layers
#pragma once
#include <optional>

#include "render/aux_layers.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/splat_film.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/ray_queues.h"
#include "shared/lt_types.h"

namespace gdr {

struct LtSettings {
  bool aux = false;
};
extern const std::vector<std::string> kLtParams;
LtSettings lt_settings(const IntegratorParams& params);

class LightTracer : public Integrator {
 public:
  LightTracer(const RenderInputs& inputs, const LtSettings& settings);

  RenderResult render(const RenderSettings& settings) override;

 private:
  // Pixels [first, first + count): their camera rays' direct emission, and as many light
  // subpaths (indices first .. first + count - 1 of the pass), into the film.
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);
  void trace_direct(const GdrPtParams& params);
  void trace_light_subpaths(const GdrPtParams& params);

  RenderInputs in_;
  LtSettings lt_;
  KernelFactory kernels_;
  Kernel camera_, direct_, emit_, shade_, shadow_;
  size_t capacity_;  // light subpaths (and camera rays) in flight at once
  RayQueues queues_;
  Buffer<GdrLightPathState> paths_;
  Buffer<GdrRay> shadow_rays_;
  DeviceCounters counters_;
  Film film_;
  SplatFilm splats_;
  std::optional<AuxLayers> aux_;
};

}  // namespace gdr
