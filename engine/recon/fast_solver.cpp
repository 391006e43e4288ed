#include "recon/fast_solver.h"

#include <utility>

namespace gdr {

FastSolver::FastSolver(Context& ctx, int width, int height)
    : grid_(width, height, recon_vector_width(ctx)),
      dots_(ctx),
      mg_(ctx, grid_),
      p_{grid_.buffer(ctx), grid_.buffer(ctx)},
      q_(grid_.buffer(ctx)),
      convergence_(ctx),
      update_p_apply_dot_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_p_apply_dot")),
      update_xr_dot_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_xr_dot")) {}

SolveOutcome FastSolver::solve(const LinearSystem& sys, int max_iterations, double tolerance,
                               bool relative_to_start, bool residual_ready) {
  const Planes& g = grid_;
  PlaneBuffer& r = *sys.r;
  SolveOutcome out;
  if (!convergence_.start(sys, dots_, max_iterations, tolerance, relative_to_start, residual_ready,
                          out)) {
    return out;
  }

  if (!mg_ready_) mg_.setup(sys);
  mg_ready_ = true;
  // Slots of r * z now and in the next iteration; beta = scal[num] / scal[den] is 0 at first.
  int rz = DeviceDots::kRZ0, rz_next = DeviceDots::kRZ1;
  int beta_num = DeviceDots::kZero, beta_den = DeviceDots::kZero;
  PlaneBuffer* z = &mg_.apply(r, dots_, rz);
  int cur = 0;  // p_[cur] holds p
  for (int it = 0; it < max_iterations; ++it) {
    update_p_apply_dot_.args(p_[cur], *z, dots_.scalars(), beta_num, beta_den, *sys.wp, *sys.wx,
                             *sys.wy, g.ws, g.h, p_[1 - cur], q_, dots_.partial());
    dots_.reduce(update_p_apply_dot_, g, DeviceDots::kPQ);
    cur = 1 - cur;
    update_xr_dot_.args(*sys.x, r, p_[cur], q_, dots_.scalars(), rz, int(DeviceDots::kPQ), g.ws,
                        g.h, dots_.partial());
    dots_.reduce(update_xr_dot_, g, DeviceDots::kRR);
    out.iterations = it + 1;
    if (convergence_.reached(dots_.read(DeviceDots::kRR), out) || it + 1 == max_iterations) break;
    z = &mg_.apply(r, dots_, rz_next);
    beta_num = rz_next;
    beta_den = rz;
    std::swap(rz, rz_next);
  }
  return out;
}

}  // namespace gdr
