#include "recon/fast_solver.h"

#include <utility>

namespace gdr {

FastSolver::FastSolver(Context& ctx, int width, int height)
    : grid_(width, height, recon_vector_width(ctx)),
      dots_(ctx),
      mg_(ctx, grid_),
      r_(grid_.buffer(ctx)),
      p_(grid_.buffer(ctx)),
      q_(grid_.buffer(ctx)),
      apply_dot_(recon_program(ctx, "recon/operator.cl")->kernel("recon_apply_dot")),
      residual_(recon_program(ctx, "recon/operator.cl")->kernel("recon_residual")),
      update_xr_dot_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_xr_dot")),
      update_p_(recon_program(ctx, "recon/cg.cl")->kernel("cg_update_p")) {}

SolveOutcome FastSolver::solve(const LinearSystem& sys, int max_iterations, double tolerance,
                               bool relative_to_start) {
  const Planes& g = grid_;
  dots_.clear();
  residual_.args(*sys.x, *sys.b, *sys.wp, *sys.wx, *sys.wy, g.ws, g.h, r_);
  g.run(residual_);
  dots_.dot(*sys.b, *sys.b, g, DeviceDots::kBB);
  dots_.dot(r_, r_, g, DeviceDots::kRR);
  const cl_float4 rr0 = dots_.read(DeviceDots::kRR);
  const cl_float4 bb = dots_.read(DeviceDots::kBB);
  // Stopping is judged against |b|, or for a warm-started IRLS round against its first residual.
  const cl_float4 ref = relative_to_start ? rr0 : bb;
  SolveOutcome out;
  out.residual = relative_residual(rr0, bb, rr0);
  if (relative_residual(rr0, ref, rr0) <= tolerance || max_iterations <= 0) return out;

  if (!mg_ready_) mg_.setup(sys);
  mg_ready_ = true;
  int rz_old = DeviceDots::kRZ0, rz_new = DeviceDots::kRZ1;
  PlaneBuffer* z = &mg_.apply(r_);
  dots_.dot(r_, *z, g, rz_old);
  p_.fill(0.0f);
  update_p_.args(p_, *z, dots_.scalars(), int(DeviceDots::kZero), int(DeviceDots::kZero), g.ws, g.h);
  g.run(update_p_);
  for (int it = 0; it < max_iterations; ++it) {
    apply_dot_.args(p_, *sys.wp, *sys.wx, *sys.wy, g.ws, g.h, q_, dots_.partial());
    dots_.reduce(apply_dot_, g, DeviceDots::kPQ);
    update_xr_dot_.args(*sys.x, r_, p_, q_, dots_.scalars(), rz_old, int(DeviceDots::kPQ), g.ws,
                        g.h, dots_.partial());
    dots_.reduce(update_xr_dot_, g, DeviceDots::kRR);
    out.iterations = it + 1;
    const cl_float4 rr = dots_.read(DeviceDots::kRR);
    out.residual = relative_residual(rr, bb, rr0);
    if (relative_residual(rr, ref, rr0) <= tolerance || it + 1 == max_iterations) break;
    z = &mg_.apply(r_);
    dots_.dot(r_, *z, g, rz_new);
    update_p_.args(p_, *z, dots_.scalars(), rz_new, rz_old, g.ws, g.h);
    g.run(update_p_);
    std::swap(rz_old, rz_new);
  }
  return out;
}

}  // namespace gdr
