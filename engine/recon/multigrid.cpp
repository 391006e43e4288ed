#include "recon/multigrid.h"

#include <utility>

namespace gdr {
namespace {
constexpr float kOmega = 0.8f;      // damped Jacobi, the usual choice for 5-point stencils
constexpr int kCoarsestSweeps = 8;  // coarse levels are dominated by the screening term
constexpr int kCoarsestPixels = 64;
}  // namespace

Multigrid::Multigrid(Context& ctx, int width, int height)
    : ctx_(ctx),
      coarsen_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_coarsen")),
      diag_(recon_program(ctx, "recon/setup.cl")->kernel("recon_diag_inv")),
      jacobi_zero_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_jacobi_zero")),
      jacobi_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_jacobi")),
      restrict_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_restrict_presmoothed")),
      correct_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_correct")) {
  int w = width, h = height;
  for (;;) {
    auto l = std::make_unique<Level>();
    l->w = w;
    l->h = h;
    size_t n = size_t(w) * h;
    if (!levels_.empty()) {
      l->own_wp = Vec4Buffer(ctx, n);
      l->own_wx = Vec4Buffer(ctx, n);
      l->own_wy = Vec4Buffer(ctx, n);
      l->own_b = Vec4Buffer(ctx, n);
      l->wp = &l->own_wp;
      l->wx = &l->own_wx;
      l->wy = &l->own_wy;
      l->b = &l->own_b;
    }
    l->dinv = Vec4Buffer(ctx, n);
    l->x = Vec4Buffer(ctx, n);
    l->tmp = Vec4Buffer(ctx, n);
    levels_.push_back(std::move(l));
    if (int(n) <= kCoarsestPixels || (w == 1 && h == 1)) break;
    w = (w + 1) / 2;
    h = (h + 1) / 2;
  }
}

void Multigrid::setup(const LinearSystem& sys) {
  Level& fine = *levels_[0];
  fine.wp = sys.wp;
  fine.wx = sys.wx;
  fine.wy = sys.wy;
  for (size_t i = 0; i < levels_.size(); ++i) {
    Level& l = *levels_[i];
    if (i > 0) {
      Level& f = *levels_[i - 1];
      coarsen_.args(*f.wp, *f.wx, *f.wy, f.w, f.h, *l.wp, *l.wx, *l.wy, l.w, l.h).run(l.n());
    }
    diag_.args(*l.wp, *l.wx, *l.wy, l.w, l.h, l.dinv).run(l.n());
  }
}

void Multigrid::smooth(Level& l, int sweeps) {
  for (int s = 0; s < sweeps; ++s) {
    jacobi_.args(l.x, *l.b, *l.wp, *l.wx, *l.wy, l.dinv, kOmega, l.w, l.h, l.tmp).run(l.n());
    std::swap(l.x, l.tmp);
  }
}

Vec4Buffer& Multigrid::apply(Vec4Buffer& r) {
  // One Jacobi sweep before and one after the coarse correction on every level; the one before
  // is fused with the residual and restriction.
  levels_[0]->b = &r;
  const size_t last = levels_.size() - 1;
  for (size_t i = 0; i < last; ++i) {
    Level& l = *levels_[i];
    Level& c = *levels_[i + 1];
    restrict_.args(*l.b, l.dinv, kOmega, *l.wp, *l.wx, *l.wy, l.w, l.h, *c.b, c.w, c.h).run(c.n());
  }
  Level& coarsest = *levels_[last];
  jacobi_zero_.args(*coarsest.b, coarsest.dinv, kOmega, coarsest.n(), coarsest.x).run(coarsest.n());
  smooth(coarsest, kCoarsestSweeps - 1);
  for (size_t i = last; i-- > 0;) {
    Level& l = *levels_[i];
    Level& c = *levels_[i + 1];
    correct_.args(*l.b, l.dinv, kOmega, c.x, c.w, l.w, l.h, l.x).run(l.n());
    smooth(l, 1);
  }
  return levels_[0]->x;
}

}  // namespace gdr
