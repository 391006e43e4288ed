// Multigrid V-cycle on 2x2 aggregates with Galerkin coarse operators (kernels/recon/multigrid.cl),
// used as a symmetric preconditioner: one damped Jacobi sweep before and one after the coarse
// correction, so z = M r is a fixed SPD linear map as PCG requires.
#pragma once
#include <memory>
#include <vector>

#include "recon/recon_system.h"

namespace gdr {

class Multigrid {
 public:
  Multigrid(Context& ctx, const Planes& fine);
  // Coarsens the weights of `sys` (call again whenever they change).
  void setup(const LinearSystem& sys);
  // Returns the buffer holding z = M r (owned by this object, valid until the next call).
  PlaneBuffer& apply(PlaneBuffer& r);
  int levels() const { return int(levels_.size()); }

 private:
  struct Level {
    explicit Level(const Planes& g) : grid(g) {}
    Planes grid;
    PlaneBuffer own_wp, own_wx, own_wy, own_b;
    PlaneBuffer *wp = nullptr, *wx = nullptr, *wy = nullptr, *b = nullptr;
    PlaneBuffer dinv, x, tmp;
  };
  void smooth(Level& l, int sweeps);
  std::vector<std::unique_ptr<Level>> levels_;
  Kernel coarsen_, diag_, jacobi_zero_, jacobi_, restrict_, correct_;
};

}  // namespace gdr
