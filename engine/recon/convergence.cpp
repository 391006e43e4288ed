#include "recon/convergence.h"

namespace gdr {

Convergence::Convergence(Context& ctx)
    : residual_(recon_program(ctx, "recon/operator.cl")->kernel("recon_residual")) {}

bool Convergence::start(const LinearSystem& sys, DeviceDots& dots, int max_iterations,
                        double tolerance, bool relative_to_start, bool residual_ready,
                        SolveOutcome& out) {
  const Planes& g = sys.grid;
  dots.clear();
  if (!residual_ready) {
    residual_.args(*sys.x, *sys.b, *sys.wp, *sys.wx, *sys.wy, g.ws, g.h, *sys.r);
    g.run(residual_);
  }
  dots.dot(*sys.b, *sys.b, g, DeviceDots::kBB);
  dots.dot(*sys.r, *sys.r, g, DeviceDots::kRR);
  rr0_ = dots.read(DeviceDots::kRR);
  bb_ = dots.read(DeviceDots::kBB);
  ref_ = relative_to_start ? rr0_ : bb_;
  tolerance_ = tolerance;
  out = SolveOutcome{};
  return !reached(rr0_, out) && max_iterations > 0;
}

bool Convergence::reached(const cl_float4& rr, SolveOutcome& out) const {
  out.residual = relative_residual(rr, bb_, rr0_);
  return relative_residual(rr, ref_, rr0_) <= tolerance_;
}

}  // namespace gdr
