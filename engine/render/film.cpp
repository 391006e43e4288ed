#include "render/film.h"

#include <algorithm>

#include "cluster/ranks.h"
#include "cluster/reduce.h"
#include "util/error.h"

namespace gdr {

Film::Film(Context& ctx, int width, int height, const std::vector<std::string>& layers)
    : width_(width), height_(height), stats_(ctx.stats()) {
  for (const std::string& name : layers) layers_.emplace(name, Buffer<Vec4>(ctx, pixels()));
}

Buffer<Vec4>& Film::operator[](const std::string& layer) {
  auto it = layers_.find(layer);
  if (it == layers_.end()) throw Error("film has no layer '" + layer + "'");
  return it->second;
}

const Buffer<Vec4>& Film::operator[](const std::string& layer) const {
  return const_cast<Film&>(*this)[layer];
}

void Film::clear() {
  for (auto& [name, buffer] : layers_) buffer.fill(Vec4{});
}

std::vector<float> Film::mean_rgb(const std::string& layer, int samples) const {
  return reduced_rgb((*this)[layer], mean_scale(samples), stats_);
}

std::vector<float> reduced_rgb(const Buffer<Vec4>& sums, float scale, Stats* stats) {
  std::vector<float> rgb = film_rgb(sums, 1.0f);
  cluster::sum_to_root(rgb, stats);
  if (scale != 1.0f) {
    for (float& v : rgb) v *= scale;
  }
  return rgb;
}

std::vector<float> film_rgb(const Buffer<Vec4>& sums, float scale) {
  std::vector<Vec4> v = sums.read();
  std::vector<float> rgb(v.size() * 3);
  for (size_t i = 0; i < v.size(); ++i) {
    rgb[3 * i + 0] = v[i].x * scale;
    rgb[3 * i + 1] = v[i].y * scale;
    rgb[3 * i + 2] = v[i].z * scale;
  }
  return rgb;
}

PassEstimate pass_estimate(const Buffer<Vec4>& sum, const Buffer<Vec4>& m2, int held, int passes, Stats* stats) {
  cluster::Moments moments{held, film_rgb(sum, 1.0f), film_rgb(m2, 1.0f)};
  cluster::combine_to_root(moments, stats);
  if (cluster::root() && moments.passes != passes) {
    throw Error("film reduction: the ranks hold " + std::to_string(moments.passes) + " passes, not " +
                std::to_string(passes));
  }
  passes = moments.passes;  // the rank's own on the others
  PassEstimate e;
  e.passes = passes;
  e.mean = moments.sum;
  const float scale = mean_scale(passes);
  for (float& v : e.mean) v *= scale;
  e.variance.assign(e.mean.size(), 0.0f);
  if (passes < 2) return e;
  const double v_scale = 1.0 / (double(passes - 1) * passes);
  for (size_t i = 0; i < moments.m2.size(); ++i) {
    e.variance[i] = float(std::max(0.0, double(moments.m2[i])) * v_scale);
  }
  return e;
}

PassEstimate combine(const PassEstimate& a, const PassEstimate& b) {
  if (b.passes == 0) return a;
  if (a.passes == 0) return b;
  const double na = a.passes, nb = b.passes, n = na + nb;
  PassEstimate e;
  e.passes = a.passes + b.passes;
  e.mean.resize(a.mean.size());
  e.variance.resize(a.mean.size());
  for (size_t i = 0; i < a.mean.size(); ++i) {
    const double ma = a.mean[i], mb = b.mean[i];
    // Summed squared deviations of each set back from its variance of the mean, then joined.
    const double m2 = double(a.variance[i]) * na * (na - 1) + double(b.variance[i]) * nb * (nb - 1) +
                      na * nb / n * (ma - mb) * (ma - mb);
    e.mean[i] = float((na * ma + nb * mb) / n);
    e.variance[i] = float(m2 / ((n - 1) * n));
  }
  return e;
}

}  // namespace gdr
