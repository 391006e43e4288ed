// The film of a gradient-domain render: the sums of primal, dx, dy and direct and the summed
// squared deviations of the first three, kept apart for the even and the odd passes. Each half
// then has its own means and variance estimates, independent of the other's, which is what the
// weighted reconstruction needs (render/gradient_images.h); the whole render's are joined from
// the two.
#pragma once
#include "render/film.h"
#include "render/gradient_images.h"

namespace gdr {

class GradientFilm {
 public:
  GradientFilm(Context& context, int width, int height);

  int width() const { return film_.width(); }
  int height() const { return film_.height(); }
  size_t pixels() const { return film_.pixels(); }
  void clear() { film_.clear(); }

  // The gather kernel's (kernels/gradient/gather.h) arguments for pass `sample` (0, 1, ...):
  // the passes its half holds with this one, then the half's primal, dx, dy, direct, primal_m2,
  // dx_m2 and dy_m2 layers.
  struct PassArgs {
    const GradientFilm* film;
    int sample;
    cl_uint bind_to(Kernel& k, cl_uint first) const;
  };
  PassArgs pass(int sample) const { return PassArgs{this, sample}; }

  // The layers after `passes` passes: the whole render's means and variances and each half's.
  GradientImages images(int passes) const;

 private:
  Film film_;
};

}  // namespace gdr
