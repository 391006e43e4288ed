#include "recon/device_dots.h"

#include <algorithm>
#include <cmath>

namespace gdr {

DeviceDots::DeviceDots(Context& ctx)
    : partial_(ctx, 3 * kMaxGroups),
      scal_(ctx, kSlotCount),
      dot_(recon_program(ctx, "recon/reduce.cl")->kernel("recon_dot_partial")),
      final_(recon_program(ctx, "recon/reduce.cl")->kernel("recon_sum_final")) {
  clear();
}

int DeviceDots::groups(const Planes& grid) {
  return int(std::clamp<size_t>((grid.chunks() + kLocal - 1) / kLocal, 1, kMaxGroups));
}

void DeviceDots::dot(const PlaneBuffer& a, const PlaneBuffer& b, const Planes& grid, int slot) {
  dot_.args(a, b, grid.ws, grid.h, partial_);
  reduce(dot_, grid, slot);
}

void DeviceDots::reduce(Kernel& k, const Planes& grid, int slot) {
  const int g = groups(grid);
  k.run_2d(size_t(g) * kLocal, 3, kLocal, 1);
  final_.args(partial_, g, scal_, slot).run_2d(kLocal, 3, kLocal, 1);
}

cl_float4 DeviceDots::read(int slot) const {
  cl_float4 v;
  scal_.read(&v, 1, size_t(slot));
  return v;
}

void DeviceDots::clear() { scal_.fill(cl_float4{{0, 0, 0, 0}}); }

double relative_residual(const cl_float4& rr, const cl_float4& bb, const cl_float4& rr0) {
  double worst = 0;
  for (int c = 0; c < 3; ++c) {
    double den = bb.s[c] > 0 ? bb.s[c] : rr0.s[c];
    double rel = den > 0 ? std::sqrt(std::max(0.0, double(rr.s[c])) / den) : 0.0;
    if (!std::isfinite(rel)) rel = 1.0;
    worst = std::max(worst, rel);
  }
  return worst;
}

}  // namespace gdr
