// G-PM's merge stage (kernels/gbidir/merge.h; G-VCM's too): after a shade step of merging groups,
// the photons within the radius of each recorded vertex are merged for the base, and shifted to
// each offset's own vertex by a ray from the photon's parent (Embree), then merged there (offsets
// at the base's vertex merge the same photons: no rays). The rays of one launch are bounded: the
// recorded groups go in slices whose photons' rays fit.
#pragma once
#include "integrators/bidir/subpaths.h"
#include "integrators/gpt/gradient_groups.h"
#include "render/wavefront/primitives.h"

namespace gdr {

class PhotonShifts {
 public:
  PhotonShifts(const RenderInputs& inputs, const GradientGroups& groups);

  // The `recorded` visible points of groups' last shade step merged with the pass's photons
  // (options o: the radius and the density estimate's normalization), into groups.acc().
  void merge(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint recorded, GradientGroups& groups,
             const PhotonGrid& photons);

 private:
  // Groups [first, first + count) of the recorded list, whose rays start at starts[first];
  // `shifted`: their photons that need rays (four each).
  void merge_slice(const GdrGptParams& p, const GdrBidirOptions& o, cl_uint first, cl_uint count, size_t shifted,
                   GradientGroups& groups, const PhotonGrid& photons);

  RenderInputs in_;
  Kernel count_, rays_, merge_;
  DevicePrimitives primitives_;
  Buffer<cl_uint> starts_;       // the recorded groups' first photon with rays, a scan of their counts
  Buffer<GdrRayHit> shift_rays_;  // four a photon
};

}  // namespace gdr
