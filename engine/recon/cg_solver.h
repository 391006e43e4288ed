// Baseline: conjugate gradients on the normal equations A x = b, all vector work in kernels; the
// host reads one float4 (the residual norms) per iteration to decide when to stop.
#pragma once
#include "recon/convergence.h"

namespace gdr {

class CgSolver {
 public:
  CgSolver(Context& ctx, int width, int height);
  // Improves sys.x in place (warm start) for at most max_iterations; stops early once the
  // relative residual is <= tolerance (when tolerance > 0): |r| / |b|, or |r| / |r0| with
  // relative_to_start. The outcome's residual is always |r| / |b|. With residual_ready, sys.r
  // already holds b - A x (else it is computed here).
  SolveOutcome solve(const LinearSystem& sys, int max_iterations, double tolerance,
                     bool relative_to_start = false, bool residual_ready = false);

 private:
  Planes grid_;
  DeviceDots dots_;
  PlaneBuffer p_, q_;
  Convergence convergence_;
  Kernel apply_, update_xr_, update_p_;
};

}  // namespace gdr
