#include "recon/device_dots.h"

#include <algorithm>
#include <cmath>

namespace gdr {

std::shared_ptr<Program> recon_program(Context& ctx, const std::string& file) {
  Defines defines;
  if (ctx.is_cpu()) defines["RECON_CONTIGUOUS"] = "";
  return ctx.program(file, defines);
}

DeviceDots::DeviceDots(Context& ctx)
    : partial_(ctx, kMaxGroups),
      scal_(ctx, kSlotCount),
      dot_(recon_program(ctx, "recon/reduce.cl")->kernel("recon_dot_partial")),
      final_(recon_program(ctx, "recon/reduce.cl")->kernel("recon_sum_final")) {
  clear();
}

int DeviceDots::groups(int n) {
  return std::clamp((n + int(kLocal) - 1) / int(kLocal), 1, kMaxGroups);
}

void DeviceDots::dot(const Vec4Buffer& a, const Vec4Buffer& b, int n, int slot) {
  dot_.args(a, b, n, partial_).run(reduce_global(n));
  sum_partials(n, slot);
}

void DeviceDots::sum_partials(int n, int slot) {
  final_.args(partial_, groups(n), scal_, slot).run(kLocal);
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
