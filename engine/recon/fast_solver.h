// The fast solver: conjugate gradients preconditioned by a multigrid V-cycle. Each iteration is
// three fused passes over the image and the V-cycle: p update with q = A p and p * q, the x/r
// update with r * r, and z = M r with r * z.
#pragma once
#include "recon/convergence.h"
#include "recon/multigrid.h"

namespace gdr {

class FastSolver {
 public:
  FastSolver(Context& ctx, int width, int height);
  // Like CgSolver::solve. The multigrid levels are built from the system's weights at the first
  // iteration that needs them; call weights_changed() when they change.
  void weights_changed() { mg_ready_ = false; }
  SolveOutcome solve(const LinearSystem& sys, int max_iterations, double tolerance,
                     bool relative_to_start = false, bool residual_ready = false);

 private:
  Planes grid_;
  DeviceDots dots_;
  Multigrid mg_;
  bool mg_ready_ = false;
  PlaneBuffer p_[2], q_;
  Convergence convergence_;
  Kernel update_p_apply_dot_, update_xr_dot_;
};

}  // namespace gdr
