// G-BDPT's (and G-VCM's) light tracing with gradients (kernels/gbidir/light_tracing.h): after each
// light bounce, the light subpaths' vertices seen by the camera (the splat film's slots) are shifted
// to the four neighbour pixels: a camera ray through each shifted film position (Embree), the
// offset vertex reconnected to the base vertex's parent (a shadow ray), then base and offsets are
// gathered into the pass's layers by film row, without atomics, as the splat film gathers. At the
// end of the pass the layers join the groups' accumulators (their pairs' slots), so that light
// tracing's share of each pixel has gradients like every other strategy's.
#pragma once
#include "integrators/bidir/subpaths.h"
#include "integrators/gpt/gradient_groups.h"
#include "render/splat_film.h"

namespace gdr {

class LightTracingShifts {
 public:
  // `slots`: the light subpaths in flight (the splat film's slots).
  LightTracingShifts(const RenderInputs& inputs, const GradientGroups& groups, size_t slots);

  // The splats of slots [0, count) after a light bounce of `subpaths` (options o), shifted and
  // gathered into the layers; the splat slots are emptied.
  void shift(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint count, const BidirSubpaths& subpaths,
             SplatFilm& splats, GradientGroups& groups);
  // Adds the pass's layers into groups.acc() and empties them.
  void end_pass(GradientGroups& groups);

 private:
  RenderInputs in_;
  Kernel rays_, eval_, blocked_, gather_, add_;
  Buffer<GdrRayHit> offset_rays_;  // four a slot at most
  Buffer<GdrRay> shadow_rays_;     // one an offset ray
  Buffer<Vec4> pairs_;             // four a slot: the offset's value and its pdf ratio R
  Buffer<Vec4> layers_;            // GBDPT_LT_LAYERS a pixel
};

}  // namespace gdr
