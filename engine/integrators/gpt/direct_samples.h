// The gradient-domain integrators' extra camera samples of the emission seen directly
// (--direct-samples K): each pass, K camera rays for each pixel that
// kernels/gradient/seen_coverage.h lists (every pixel in the first pass, then those near an
// emitter's edge), their emission into the groups' GPT_ACC_SEEN (render/seen_emission.h). The
// gather (kernels/gradient/gather.h) takes the mean over the base's sample and these, and updates
// each pixel's flags from what they saw.
#pragma once
#include <optional>

#include "render/seen_emission.h"

namespace gdr {

class DirectSamples {
 public:
  // `samples`: K (0: none, and nothing built); rays in flight at most `capacity`.
  DirectSamples(const RenderInputs& inputs, const KernelFactory& kernels, const std::string& program, int samples,
                int width, int height, size_t capacity);

  int samples() const { return samples_; }
  // The gather's: each pixel's flags, and whether it took the pass's extra samples (one entry
  // each when K is 0).
  Buffer<cl_uint>& flags() { return flags_; }
  const Buffer<cl_uint>& taking() const { return taking_; }
  // A new render: every pixel takes extra samples in its first pass.
  void clear();
  // The pass of `p` (its seed, sample and scene): the listed pixels' samples into `acc`.
  void add(const GdrPtParams& p, Buffer<Vec4>& acc);
  void report(Stats* stats);

 private:
  int samples_;
  int width_, height_;
  size_t capacity_;
  Buffer<cl_uint> flags_, taking_, list_;
  Buffer<GdrRayHit> rays_;
  std::optional<Kernel> list_kernel_;
  std::optional<SeenEmission> seen_;
};

}  // namespace gdr
