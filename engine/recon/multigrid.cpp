#include "recon/multigrid.h"

#include <algorithm>
#include <utility>

namespace gdr {
namespace {
constexpr int kCoarsestSweeps = 8;  // coarse levels are dominated by the screening term
constexpr int kCoarsestPixels = 64;

// Work items per plane of the fine-to-coarse kernels: one per MG_ITEM_COLS fine columns
// (kernels/recon/multigrid.cl) of each pair of fine rows.
size_t transfer_items(const Planes& fine, const Planes& coarse) {
  return size_t(fine.ws) / size_t(std::max(2, fine.vec)) * size_t(coarse.h);
}
}  // namespace

Multigrid::Multigrid(Context& ctx, const Planes& fine)
    : coarsen_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_coarsen")),
      jacobi_zero_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_jacobi_zero")),
      jacobi_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_jacobi")),
      restrict_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_restrict_presmoothed")),
      correct_smooth_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_correct_smooth")),
      correct_smooth_dot_(recon_program(ctx, "recon/multigrid.cl")->kernel("mg_correct_smooth_dot")) {
  Planes g = fine;
  for (;;) {
    auto l = std::make_unique<Level>(g);
    if (!levels_.empty()) {
      l->own_wp = g.buffer(ctx);
      l->own_wx = g.buffer(ctx);
      l->own_wy = g.buffer(ctx);
      l->own_step = g.buffer(ctx);
      l->own_b = g.buffer(ctx);
      l->wp = &l->own_wp;
      l->wx = &l->own_wx;
      l->wy = &l->own_wy;
      l->step = &l->own_step;
      l->b = &l->own_b;
    }
    l->x = g.buffer(ctx);
    const bool coarsest = g.w * g.h <= kCoarsestPixels || (g.w == 1 && g.h == 1);
    if (coarsest) l->tmp = g.buffer(ctx);  // only the coarsest level smooths on its own
    levels_.push_back(std::move(l));
    if (coarsest) break;
    g = g.coarse();
  }
}

void Multigrid::setup(const LinearSystem& sys) {
  Level& fine = *levels_[0];
  fine.wp = sys.wp;
  fine.wx = sys.wx;
  fine.wy = sys.wy;
  fine.step = sys.step;
  for (size_t i = 1; i < levels_.size(); ++i) {
    Level &l = *levels_[i], &f = *levels_[i - 1];
    coarsen_.args(*f.wp, *f.wx, *f.wy, f.grid.ws, f.grid.h, *l.wp, *l.wx, *l.wy, *l.step, l.grid.ws,
                  l.grid.h)
        .run_2d(transfer_items(f.grid, l.grid), 3, 64, 1);
  }
}

void Multigrid::smooth(Level& l, int sweeps) {
  const Planes& g = l.grid;
  for (int s = 0; s < sweeps; ++s) {
    jacobi_.args(l.x, *l.b, *l.wp, *l.wx, *l.wy, *l.step, g.ws, g.h, l.tmp);
    g.run(jacobi_);
    std::swap(l.x, l.tmp);
  }
}

PlaneBuffer& Multigrid::apply(PlaneBuffer& r, DeviceDots& dots, int slot) {
  levels_[0]->b = &r;
  const size_t last = levels_.size() - 1;
  for (size_t i = 0; i < last; ++i) {
    Level& l = *levels_[i];
    Level& c = *levels_[i + 1];
    const Planes &f = l.grid, &g = c.grid;
    restrict_.args(*l.b, *l.step, *l.wp, *l.wx, *l.wy, f.ws, f.h, *c.b, g.ws, g.h)
        .run_2d(transfer_items(f, g), 3, 64, 1);
  }
  Level& coarsest = *levels_[last];
  const Planes& cg = coarsest.grid;
  jacobi_zero_.args(*coarsest.b, *coarsest.step, cg.ws, cg.h, coarsest.x);
  cg.run(jacobi_zero_);
  smooth(coarsest, kCoarsestSweeps - 1);
  for (size_t i = last; i-- > 0;) {
    Level &l = *levels_[i], &c = *levels_[i + 1];
    const Planes &f = l.grid, &g = c.grid;
    if (i == 0) {
      correct_smooth_dot_.args(*l.b, *l.step, *l.wp, *l.wx, *l.wy, c.x, g.ws, g.h, f.ws, f.h, l.x,
                               dots.partial());
      dots.reduce(correct_smooth_dot_, f, slot);
    } else {
      correct_smooth_.args(*l.b, *l.step, *l.wp, *l.wx, *l.wy, c.x, g.ws, g.h, f.ws, f.h, l.x);
      f.run(correct_smooth_);
    }
  }
  if (last == 0) dots.dot(r, coarsest.x, coarsest.grid, slot);
  return levels_[0]->x;
}

}  // namespace gdr
