// G-BDPT's (and G-VCM's) light tracing with gradients (kernels/gbidir/light_tracing.h): after each
// light bounce, the light subpaths' vertices seen by the camera (the splat film's slots) are shifted
// to the four neighbour pixels: a camera ray through each shifted film position (Embree), the
// offset vertex reconnected to the base vertex's parent (a shadow ray), or, behind a delta vertex
// under the manifold shift, joined to the chain by a manifold walk; then base and offsets are
// gathered into the pass's layers by film row, without atomics, as the splat film gathers. At the
// end of the pass the layers join the groups' accumulators (their pairs' slots), so that light
// tracing's share of each pixel has gradients like every other strategy's.
#pragma once
#include <optional>

#include "integrators/bidir/subpaths.h"
#include "integrators/gpt/gradient_groups.h"
#include "render/manifold_walks.h"
#include "render/splat_film.h"

namespace gdr {

class LightTracingShifts {
 public:
  // `slots`: the light subpaths in flight (the splat film's slots). `walks`: vertices behind delta
  // vertices are shifted by manifold walks (groups' program built with GDR_MANIFOLD, the subpaths
  // keeping their delta vertices' points).
  LightTracingShifts(const RenderInputs& inputs, const GradientGroups& groups, size_t slots, bool walks = false,
                     const ManifoldSettings& manifold = {});

  // The splats of slots [0, count) after a light bounce of `subpaths` (options o), shifted and
  // gathered into the layers; the splat slots are emptied.
  void shift(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint count, const BidirSubpaths& subpaths,
             SplatFilm& splats, GradientGroups& groups);
  // Adds the pass's layers into groups.acc() and empties them.
  void end_pass(GradientGroups& groups);
  // Adds the manifold stage's counters to the stats (nothing without walks).
  void report(Stats* stats);

 private:
  RenderInputs in_;
  Kernel rays_, eval_, blocked_, gather_, add_;
  Buffer<GdrRayHit> offset_rays_;  // four a slot at most
  Buffer<GdrRay> shadow_rays_;     // one an offset ray
  Buffer<Vec4> pairs_;             // four a slot: the offset's value and its pdf ratio R
  Buffer<Vec4> layers_;            // GBDPT_LT_LAYERS a pixel
  // The manifold shift: at most a walk an offset ray, each ray's walk (or GPM_NO_WALK).
  std::optional<Kernel> walk_kernel_;
  std::optional<ManifoldWalks> manifold_;
  Buffer<cl_uint> walk_of_;
  Buffer<GdrManifoldWalk> walks_;
  Buffer<GdrManifoldResult> walk_results_;
};

}  // namespace gdr
