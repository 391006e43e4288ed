// The primary-sample-space numbers a kernel reads through the sampler seam
// (kernels/sampling/path_sampler.h: PRIMARY_SAMPLE_ARGS): the states of Metropolis chains and
// their layout, or none, and the paths draw from the counter-based generator.
#pragma once
#include "device/context.h"
#include "shared/sampler_types.h"

namespace gdr {

class PrimarySamples {
 public:
  PrimarySamples() = default;  // none
  PrimarySamples(const Buffer<float>& states, const GdrPrimaryLayout& layout) : states_(&states), layout_(layout) {}

  // The layout of chains holding every block a bidirectional path of at most `segments` segments
  // reads (its length and strategy among them), or with camera_only a camera path's.
  static GdrPrimaryLayout layout_for(size_t chains, int segments, bool camera_only = false);

  const GdrPrimaryLayout& layout() const { return layout_; }
  cl_uint bind_to(Kernel& kernel, cl_uint first) const;

 private:
  const Buffer<float>* states_ = nullptr;
  GdrPrimaryLayout layout_{};
};

}  // namespace gdr
