// Dot products and other reductions kept on the device: a work-group partial pass, then one group
// writes the sum into a slot of a small scalar buffer that the CG kernels read in place.
#pragma once
#include "device/context.h"

namespace gdr {

using Vec4Buffer = Buffer<cl_float4>;

// Builds (once per context) a kernels/recon program with the defines for this device.
std::shared_ptr<Program> recon_program(Context& ctx, const std::string& file);

class DeviceDots {
 public:
  enum Slot { kZero = 0, kBB, kRR, kRZ0, kRZ1, kPQ, kEnergy, kSlotCount };
  static constexpr int kMaxGroups = 128;
  static constexpr size_t kLocal = 64;

  explicit DeviceDots(Context& ctx);

  // scal[slot] = sum over i < n of a[i] * b[i], per channel.
  void dot(const Vec4Buffer& a, const Vec4Buffer& b, int n, int slot);
  // scal[slot] = sum of the partials a fused kernel wrote for `n` items.
  void sum_partials(int n, int slot);
  cl_float4 read(int slot) const;
  void clear();

  // Global size for a kernel that reduces over n items into partial().
  static size_t reduce_global(int n) { return size_t(groups(n)) * kLocal; }
  static int groups(int n);
  Vec4Buffer& partial() { return partial_; }
  Vec4Buffer& scalars() { return scal_; }

 private:
  Vec4Buffer partial_, scal_;
  Kernel dot_, final_;
};

// Largest per-channel sqrt(rr / bb) over R, G, B; `rr0` stands in for a zero bb.
double relative_residual(const cl_float4& rr, const cl_float4& bb, const cl_float4& rr0);

}  // namespace gdr
