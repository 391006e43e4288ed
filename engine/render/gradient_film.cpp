#include "render/gradient_film.h"

#include "render/pass_schedule.h"

namespace gdr {
namespace {

// Film layer `name` of half h (0: even passes, 1: odd).
std::string layer(const char* name, int h) { return std::string(h == 0 ? "even." : "odd.") + name; }

const char* const kLayers[] = {"primal", "dx", "dy", "direct", "primal_m2", "dx_m2", "dy_m2"};

// Passes of half h among the first `passes` of all ranks.
int half_passes(int passes, int h) { return h == 0 ? (passes + 1) / 2 : passes / 2; }

std::vector<std::string> layer_names() {
  std::vector<std::string> names;
  for (int h = 0; h < 2; ++h) {
    for (const char* l : kLayers) names.push_back(layer(l, h));
  }
  return names;
}

}  // namespace

GradientFilm::GradientFilm(Context& context, int width, int height) : film_(context, width, height, layer_names()) {}

cl_uint GradientFilm::PassArgs::bind_to(Kernel& k, cl_uint first) const {
  const int h = sample % 2;
  cl_uint i = first;
  // The sums are this rank's: the count is that of its own passes of the half, this one included.
  k.set_arg(i++, cl_int(PassSchedule::of_this_process().held(sample + 1, h)));
  for (const char* l : kLayers) k.set_arg(i++, film->film_[layer(l, h)]);
  return i - first;
}

GradientImages GradientFilm::images(int passes) const {
  GradientImages out;
  out.width = width();
  out.height = height();
  out.samples = passes;
  const PassSchedule schedule = PassSchedule::of_this_process();
  PassEstimate whole[3];
  std::vector<float> direct(pixels() * 3, 0.0f);
  for (int h = 0; h < 2; ++h) {
    const int n = half_passes(passes, h);
    if (n == 0) continue;
    GradientLayers& half = out.halves[h];
    PassEstimate e[3];
    for (int q = 0; q < 3; ++q) {
      e[q] = pass_estimate(film_[layer(kLayers[q], h)], film_[layer(kLayers[4 + q], h)], schedule.held(passes, h), n,
                           film_.stats());
      whole[q] = combine(whole[q], e[q]);
    }
    half.primal = e[0].mean;
    half.dx = e[1].mean;
    half.dy = e[2].mean;
    half.primal_variance = e[0].variance;
    half.dx_variance = e[1].variance;
    half.dy_variance = e[2].variance;
    half.direct = reduced_rgb(film_[layer("direct", h)], mean_scale(n), film_.stats());
    for (size_t i = 0; i < direct.size(); ++i) direct[i] += half.direct[i] * (float(n) / float(passes));
  }
  for (PassEstimate& e : whole) {  // no passes at all: zero images
    if (e.passes == 0) e.mean = e.variance = std::vector<float>(pixels() * 3, 0.0f);
  }
  out.primal = whole[0].mean;
  out.dx = whole[1].mean;
  out.dy = whole[2].mean;
  out.direct = direct;
  out.primal_variance = whole[0].variance;
  out.dx_variance = whole[1].variance;
  out.dy_variance = whole[2].variance;
  return out;
}

}  // namespace gdr
