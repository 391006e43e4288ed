// The fast solver: conjugate gradients preconditioned by a multigrid V-cycle, with the operator
// apply fused with its dot product and the x/r update fused with the residual norm.
#pragma once
#include "recon/multigrid.h"

namespace gdr {

class FastSolver {
 public:
  FastSolver(Context& ctx, int width, int height);
  // Like CgSolver::solve; call setup() after the weights of `sys` change.
  // (The multigrid levels are built at the first iteration that needs them.)
  void setup(const LinearSystem&) { mg_ready_ = false; }
  SolveOutcome solve(const LinearSystem& sys, int max_iterations, double tolerance,
                     bool relative_to_start = false);

 private:
  Planes grid_;
  DeviceDots dots_;
  Multigrid mg_;
  bool mg_ready_ = false;
  PlaneBuffer r_, p_, q_;
  Kernel apply_dot_, residual_, update_xr_dot_, update_p_;
};

}  // namespace gdr
