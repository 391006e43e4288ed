#include "recon/cg_solver.h"

#include <utility>

namespace gdr {

CgSolver::CgSolver(Context& ctx, int width, int height)
    : grid_(width, height, recon_vector_width(ctx)),
      dots_(ctx),
      p_(grid_.buffer(ctx)),
      q_(grid_.buffer(ctx)),
      convergence_(ctx),
      apply_(recon_program(ctx, "recon/operator.cl")->kernel("recon_apply")),
      update_xr_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_xr")),
      update_p_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_p")) {}

SolveOutcome CgSolver::solve(const LinearSystem& sys, int max_iterations, double tolerance,
                             bool relative_to_start, bool residual_ready) {
  const Planes& g = grid_;
  PlaneBuffer& r = *sys.r;
  SolveOutcome out;
  if (!convergence_.start(sys, dots_, max_iterations, tolerance, relative_to_start, residual_ready,
                          out)) {
    return out;
  }
  int rr_old = DeviceDots::kRR, rr_new = DeviceDots::kRZ0;

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
    const bool done = convergence_.reached(dots_.read(rr_new), out);
    std::swap(rr_old, rr_new);
    if (done) break;
  }
  return out;
}

}  // namespace gdr
