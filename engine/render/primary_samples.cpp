#include "render/primary_samples.h"

static_assert(sizeof(GdrPrimaryLayout) == 16, "GdrPrimaryLayout layout changed");

namespace gdr {

GdrPrimaryLayout PrimarySamples::layout_for(size_t chains, int segments, bool camera_only) {
  GdrPrimaryLayout l{};
  l.chains = cl_uint(chains);
  l.camera_only = camera_only ? 1u : 0u;
  l.blocks = cl_uint(camera_only ? GDR_PRIMARY_CAMERA_BLOCKS(segments) : GDR_PRIMARY_BLOCKS(segments));
  return l;
}

cl_uint PrimarySamples::bind_to(Kernel& kernel, cl_uint first) const {
  static const Buffer<float> none;  // a null buffer argument: the kernels read it only under chains
  kernel.set_arg(first, states_ ? *states_ : none);
  kernel.set_arg(first + 1, layout_);
  return 2;
}

}  // namespace gdr
