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
  Multigrid(Context& ctx, int width, int height);
  // Coarsens the weights of `sys` (call again whenever they change).
  void setup(const LinearSystem& sys);
  // Returns the buffer holding z = M r (owned by this object, valid until the next call).
  Vec4Buffer& apply(Vec4Buffer& r);
  int levels() const { return int(levels_.size()); }

 private:
  struct Level {
    int w = 0, h = 0;
    Vec4Buffer own_wp, own_wx, own_wy, own_b;
    Vec4Buffer *wp = nullptr, *wx = nullptr, *wy = nullptr, *b = nullptr;
    Vec4Buffer dinv, x, tmp;
    int n() const { return w * h; }
  };
  void smooth(Level& l, int sweeps);
  Context& ctx_;
  std::vector<std::unique_ptr<Level>> levels_;
  Kernel coarsen_, diag_, jacobi_zero_, jacobi_, restrict_, correct_;
};

}  // namespace gdr
