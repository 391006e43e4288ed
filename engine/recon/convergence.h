// What the conjugate-gradient solvers share around their iterations: the start (r = b - A x
// unless the caller already has it, |b|^2 and |r|^2 per channel) and the stopping test.
#pragma once
#include "recon/recon_system.h"

namespace gdr {

class Convergence {
 public:
  explicit Convergence(Context& ctx);
  // Clears `dots`, fills its kBB and kRR slots for sys, and sets out.residual = |r| / |b|.
  // Returns false when there is nothing to iterate: x already meets the tolerance (|r| / |b|, or
  // |r| / |r0| with relative_to_start: a warm-started IRLS round against its first residual), or
  // max_iterations <= 0.
  bool start(const LinearSystem& sys, DeviceDots& dots, int max_iterations, double tolerance,
             bool relative_to_start, bool residual_ready, SolveOutcome& out);
  // Records |r|^2 = rr in out.residual; true once it meets the tolerance.
  bool reached(const cl_float4& rr, SolveOutcome& out) const;

 private:
  Kernel residual_;
  cl_float4 rr0_{}, bb_{}, ref_{};
  double tolerance_ = 0;
};

}  // namespace gdr
