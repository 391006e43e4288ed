// G-PM's merge stage (kernels/gbidir/merge.h; G-VCM's too): after a shade step of merging groups,
// the photons within the radius of each recorded vertex are merged for the base, and shifted to
// each offset's own vertex by a ray from the photon's parent (Embree), then merged there (offsets
// at the base's vertex merge the same photons: no rays). The rays of one launch are bounded: the
// recorded groups go in slices whose photons' rays fit. Where gpm walks (--shift manifold in a
// scene with specular chains), a photon whose parent is a delta vertex is shifted by a manifold
// walk (kernels/gbidir/photon_chain.h), solved between Embree and the merges by the manifold stage
// (render/manifold_walks.h); the light subpaths must keep their delta vertices' points
// (BidirSubpaths::record_delta_points).
#pragma once
#include <optional>

#include "integrators/bidir/subpaths.h"
#include "integrators/gpt/gradient_groups.h"
#include "render/manifold_walks.h"
#include "render/wavefront/primitives.h"

namespace gdr {

class PhotonShifts {
 public:
  // The photon walks' Newton iterations where manifold_iterations is not given: capped low, as
  // the reference's (Hua et al. 2017: 5). Measured on the caustics box (gpm --shift manifold,
  // 64 px, 8 passes, medians of 3): 93% of the shifts that 20 iterations solve, in 47% of the
  // walks' time (the render 0.81 times as long).
  static constexpr int kWalkIterations = 5;

  // `walks`: photons behind delta vertices are shifted by manifold walks (groups' program built
  // with them: GDR_GPM and GDR_MANIFOLD).
  PhotonShifts(const RenderInputs& inputs, const GradientGroups& groups, bool walks = false,
               const ManifoldSettings& manifold = {});

  // The `recorded` visible points of groups' last shade step merged with the pass's photons
  // (options o: the radius and the density estimate's normalization), into groups.acc().
  void merge(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint recorded, GradientGroups& groups,
             const PhotonGrid& photons);
  // Adds the manifold stage's counters to the stats (nothing without walks).
  void report(Stats* stats);

 private:
  // Groups [first, first + count) of the recorded list, whose rays start at starts[first];
  // `shifted`: their photons that need rays (four each).
  void merge_slice(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint first, cl_uint count, size_t shifted,
                   GradientGroups& groups, const PhotonGrid& photons);

  RenderInputs in_;
  size_t max_rays_;  // shift rays in flight at most
  Kernel count_, rays_, merge_;
  DevicePrimitives primitives_;
  Buffer<cl_uint> starts_;       // the recorded groups' first photon with rays, a scan of their counts
  Buffer<cl_uint> lists_, listed_;  // each recorded group's photons (GPM_LISTED at most) and their number
  Buffer<GdrRayHit> shift_rays_;  // four a photon
  // The manifold photon shift: at most a walk a ray, each ray's walk (or GPM_NO_WALK).
  std::optional<Kernel> walk_kernel_, reverse_kernel_;
  std::optional<ManifoldWalks> manifold_;
  Buffer<cl_uint> walk_of_;
  Buffer<GdrManifoldWalk> walks_;
  Buffer<GdrManifoldResult> walk_results_;
  Buffer<GdrRay> reverse_rays_;  // each solved walk's chain back to the base photon
};

}  // namespace gdr
