// The reconstruction problem on the device: packed inputs (absent terms as NaN), the current
// term weights, right-hand side and estimate, and the kernels that build them. Every buffer has
// the planar layout of recon/planes.h.
#pragma once
#include <vector>

#include "recon/device_dots.h"
#include "recon/reconstruct.h"

namespace gdr {

// A linear system A x = b of the screened Poisson form (see kernels/recon/grid.h), with the
// damped Jacobi step omega / diag(A) (kernels/recon/grid.h) and room for the residual r = b - A x.
struct LinearSystem {
  Planes grid;
  PlaneBuffer* wp = nullptr;
  PlaneBuffer* wx = nullptr;
  PlaneBuffer* wy = nullptr;
  PlaneBuffer* step = nullptr;
  PlaneBuffer* b = nullptr;
  PlaneBuffer* x = nullptr;
  PlaneBuffer* r = nullptr;
};

// Outcome of one linear solve.
struct SolveOutcome {
  int iterations = 0;
  double residual = 0;  // relative, worst channel
};

class ReconSystem {
 public:
  // Uploads and packs the inputs (sizes already checked); x starts at the primal.
  ReconSystem(Context& ctx, int width, int height, const std::vector<float>& primal_rgb,
              const std::vector<float>& dx_rgb, const std::vector<float>& dy_rgb);
  // Buffers only; load() before use.
  ReconSystem(Context& ctx, int width, int height);
  // Replaces the inputs (the same size) and restarts x at the primal.
  void load(const std::vector<float>& primal_rgb, const std::vector<float>& dx_rgb,
            const std::vector<float>& dy_rgb);

  unsigned nonfinite_inputs() const { return nonfinite_inputs_; }
  // Root mean square of the (finite) primal over all pixels, the largest of R, G, B.
  double primal_rms() const { return primal_rms_; }
  // Weights and Jacobi step of the L2 system (b is left to build_rhs).
  void set_l2_weights(float alpha);
  // IRLS weights 1/(|e| + reg) from the current estimate x, with the Jacobi step, b, and the
  // residual r = b - A x of x.
  void set_l1_weights(float alpha, float reg);
  // Weights of the inverse-variance weighted L2 system (kernels/recon/setup.cl:
  // recon_weights_variance) from per-pixel variance estimates of the loaded inputs (sizes
  // already checked), with the Jacobi step; b is left to build_rhs. Non-finite estimates are
  // added to nonfinite_inputs().
  void set_variance_weights(const ReconVariance& variance, float alpha, float floor_rel);
  // b from the current weights.
  void build_rhs();
  // Objective value of x (sum over channels) in the L1 or L2 norm.
  double energy(float alpha, bool l2);
  // Objective value of x with the current weights (sum over channels of w e^2).
  double weighted_energy();
  // x as interleaved RGB, always finite.
  std::vector<float> result(unsigned* nonfinite_outputs);

  LinearSystem system();
  const Planes& grid() const { return grid_; }

 private:
  Planes grid_;
  unsigned nonfinite_inputs_ = 0;
  double primal_rms_ = 0;
  DeviceDots dots_;
  PlaneBuffer P_, Gx_, Gy_, wp_, wx_, wy_, step_, b_, x_, r_;
  Buffer<float> primal_in_, dx_in_, dy_in_, rgb_out_;
  Buffer<cl_uint> count_;
  Kernel pack_, weights_l2_, weights_l1_, weights_variance_, step_kernel_, rhs_, energy_, energy_weighted_,
      unpack_;
};

}  // namespace gdr
