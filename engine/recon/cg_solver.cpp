#include "recon/cg_solver.h"

#include <utility>

namespace gdr {

CgSolver::CgSolver(Context& ctx, int width, int height)
    : grid_(width, height, recon_vector_width(ctx)),
      dots_(ctx),
      p_(grid_.buffer(ctx)),
      q_(grid_.buffer(ctx)),
      apply_(recon_program(ctx, "recon/operator.cl")->kernel("recon_apply")),
      residual_(recon_program(ctx, "recon/operator.cl")->kernel("recon_residual")),
      update_xr_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_xr")),
      update_p_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_p")) {}

SolveOutcome CgSolver::solve(const LinearSystem& sys, int max_iterations, double tolerance,
                             bool relative_to_start, bool residual_ready) {
  const Planes& g = grid_;
  dots_.clear();
  PlaneBuffer& r = *sys.r;
  if (!residual_ready) {
    residual_.args(*sys.x, *sys.b, *sys.wp, *sys.wx, *sys.wy, g.ws, g.h, r);
    g.run(residual_);
  }
  dots_.dot(*sys.b, *sys.b, g, DeviceDots::kBB);
  int rr_old = DeviceDots::kRR, rr_new = DeviceDots::kRZ0;
  dots_.dot(r, r, g, rr_old);
  const cl_float4 rr0 = dots_.read(rr_old);
  const cl_float4 bb = dots_.read(DeviceDots::kBB);
  // Stopping is judged against |b|, or for a warm-started IRLS round against its first residual.
  const cl_float4 ref = relative_to_start ? rr0 : bb;
  SolveOutcome out;
  out.residual = relative_residual(rr0, bb, rr0);
  if (relative_residual(rr0, ref, rr0) <= tolerance || max_iterations <= 0) return out;

  // p = r (beta = 0 / 0 -> 0; p is zeroed first so stale contents cannot leak in).
  p_.fill(0.0f);
  update_p_.args(p_, r, dots_.scalars(), int(DeviceDots::kZero), int(DeviceDots::kZero), g.ws, g.h);
  g.run(update_p_);
  for (int it = 0; it < max_iterations; ++it) {
    apply_.args(p_, *sys.wp, *sys.wx, *sys.wy, g.ws, g.h, q_);
    g.run(apply_);
    dots_.dot(p_, q_, g, DeviceDots::kPQ);
    update_xr_.args(*sys.x, r, p_, q_, dots_.scalars(), rr_old, int(DeviceDots::kPQ), g.ws, g.h);
    g.run(update_xr_);
    dots_.dot(r, r, g, rr_new);
    update_p_.args(p_, r, dots_.scalars(), rr_new, rr_old, g.ws, g.h);
    g.run(update_p_);
    out.iterations = it + 1;
    const cl_float4 rr = dots_.read(rr_new);
    out.residual = relative_residual(rr, bb, rr0);
    std::swap(rr_old, rr_new);
    if (relative_residual(rr, ref, rr0) <= tolerance) break;
  }
  return out;
}

}  // namespace gdr
