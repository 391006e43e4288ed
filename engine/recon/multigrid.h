// Multigrid V-cycle on 2x2 aggregates with Galerkin coarse operators (kernels/recon/multigrid.cl),
// used as a symmetric preconditioner: one damped Jacobi sweep before and one after the coarse
// correction, so z = M r is a fixed SPD linear map as PCG requires. The sweep before is fused with
// the residual and restriction, the one after with the correction.
#pragma once
#include <memory>
#include <vector>

#include "recon/recon_system.h"

namespace gdr {

class Multigrid {
 public:
  Multigrid(Context& ctx, const Planes& fine);
  // Coarsens the weights of `sys` (call again whenever they change); the finest level uses the
  // system's own weights and Jacobi step.
  void setup(const LinearSystem& sys);
  // Returns the buffer holding z = M r (owned by this object, valid until the next call), and
  // puts r * z into `slot` of `dots`.
  PlaneBuffer& apply(PlaneBuffer& r, DeviceDots& dots, int slot);
  int levels() const { return int(levels_.size()); }

 private:
  struct Level {
    explicit Level(const Planes& g) : grid(g) {}
    Planes grid;
    PlaneBuffer own_wp, own_wx, own_wy, own_step, own_b;
    PlaneBuffer *wp = nullptr, *wx = nullptr, *wy = nullptr, *step = nullptr, *b = nullptr;
    PlaneBuffer x, tmp;  // tmp: the coarsest level's Jacobi sweeps
  };
  void smooth(Level& l, int sweeps);
  std::vector<std::unique_ptr<Level>> levels_;
  Kernel coarsen_, jacobi_zero_, jacobi_, restrict_, correct_smooth_, correct_smooth_dot_;
};

}  // namespace gdr
