// Dot products and other reductions kept on the device: a work-group partial pass per channel,
// then one group per channel writes the sum into its lane of a float4 slot of a small scalar
// buffer that the CG kernels read in place.
#pragma once
#include "recon/planes.h"

namespace gdr {

class DeviceDots {
 public:
  enum Slot { kZero = 0, kBB, kRR, kRZ0, kRZ1, kPQ, kEnergy, kSlotCount };
  static constexpr int kMaxGroups = 128;
  static constexpr size_t kLocal = 64;

  explicit DeviceDots(Context& ctx);

  // scal[slot] = sum over the pixels of a * b, per channel.
  void dot(const PlaneBuffer& a, const PlaneBuffer& b, const Planes& grid, int slot);
  // Runs a kernel that reduces over `grid` into partial() (its arguments set), then sums the
  // partials into scal[slot].
  void reduce(Kernel& k, const Planes& grid, int slot);
  cl_float4 read(int slot) const;
  void clear();

  PlaneBuffer& partial() { return partial_; }
  Buffer<cl_float4>& scalars() { return scal_; }

 private:
  static int groups(const Planes& grid);
  PlaneBuffer partial_;
  Buffer<cl_float4> scal_;
  Kernel dot_, final_;
};

// Largest per-channel sqrt(rr / bb) over R, G, B; `rr0` stands in for a zero bb.
double relative_residual(const cl_float4& rr, const cl_float4& bb, const cl_float4& rr0);

}  // namespace gdr
