#include "recon/fast_solver.h"

#include <utility>

namespace gdr {

FastSolver::FastSolver(Context& ctx, int width, int height)
    : grid_(width, height, recon_vector_width(ctx)),
      dots_(ctx),
      mg_(ctx, grid_),
      p_{grid_.buffer(ctx), grid_.buffer(ctx)},
      q_(grid_.buffer(ctx)),
      residual_(recon_program(ctx, "recon/operator.cl")->kernel("recon_residual")),
      update_p_apply_dot_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_p_apply_dot")),
      update_xr_dot_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_xr_dot")) {}

SolveOutcome FastSolver::solve(const LinearSystem& sys, int max_iterations, double tolerance,
                               bool relative_to_start, bool residual_ready) {
  const Planes& g = grid_;
  dots_.clear();
  PlaneBuffer& r = *sys.r;
  if (!residual_ready) {
    residual_.args(*sys.x, *sys.b, *sys.wp, *sys.wx, *sys.wy, g.ws, g.h, r);
    g.run(residual_);
  }
  dots_.dot(*sys.b, *sys.b, g, DeviceDots::kBB);
  dots_.dot(r, r, g, DeviceDots::kRR);
  const cl_float4 rr0 = dots_.read(DeviceDots::kRR);
  const cl_float4 bb = dots_.read(DeviceDots::kBB);
  // Stopping is judged against |b|, or for a warm-started IRLS round against its first residual.
  const cl_float4 ref = relative_to_start ? rr0 : bb;
  SolveOutcome out;
  out.residual = relative_residual(rr0, bb, rr0);
  if (relative_residual(rr0, ref, rr0) <= tolerance || max_iterations <= 0) return out;

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
    const cl_float4 rr = dots_.read(DeviceDots::kRR);
    out.residual = relative_residual(rr, bb, rr0);
    if (relative_residual(rr, ref, rr0) <= tolerance || it + 1 == max_iterations) break;
    z = &mg_.apply(r, dots_, rz_next);
    beta_num = rz_next;
    beta_den = rz;
    std::swap(rz, rz_next);
  }
  return out;
}

}  // namespace gdr
