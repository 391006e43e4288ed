#include "render/environment_distribution.h"

#include <cmath>

#include "shared/color.h"
#include "shared/environment_table.h"

namespace gdr {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Walker's alias table of `masses` (uniform when they sum to zero), by Vose's method: entry i at
// out[2 i] holds the probability of keeping interval i when u n falls in bucket i, and out[2 i + 1]
// the interval taken otherwise. Bucket i's share of interval j plus the shares other buckets hand
// to j add up to j's mass.
void write_alias(const std::vector<double>& masses, float* out) {
  const size_t n = masses.size();
  double total = 0;
  for (double m : masses) total += m;
  std::vector<double> scaled(n);
  std::vector<size_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    scaled[i] = total > 0 ? masses[i] * static_cast<double>(n) / total : 1.0;
    (scaled[i] < 1.0 ? small : large).push_back(i);
  }
  while (!small.empty() && !large.empty()) {
    const size_t s = small.back(), l = large.back();
    small.pop_back();
    out[2 * s] = static_cast<float>(scaled[s]);
    out[2 * s + 1] = static_cast<float>(l);
    scaled[l] = (scaled[l] + scaled[s]) - 1.0;  // what l has left after filling s's bucket
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // What remains is 1 up to rounding: those buckets keep their own interval.
  for (size_t i : small) out[2 * i] = 1.0f, out[2 * i + 1] = static_cast<float>(i);
  for (size_t i : large) out[2 * i] = 1.0f, out[2 * i + 1] = static_cast<float>(i);
}

// Mean of sin(theta) over the latitudes nearer to row r (at theta = pi r / (h - 1)) than to its
// neighbours. Unlike sin(theta_r) it is positive on the poles' rows, so the sampled density
// covers every direction where the map is bright, also the caps between a pole and the next row.
double band_sine(int r, int h) {
  double step = kPi / (h - 1), theta = r * step;
  double lo = std::fmax(0.0, theta - 0.5 * step), hi = std::fmin(kPi, theta + 0.5 * step);
  return (std::cos(lo) - std::cos(hi)) / (hi - lo);
}

}  // namespace

void build_environment_tables(const Scene& scene, std::vector<GdrLight>& lights, std::vector<float>& tables,
                              std::vector<Vec4>& texels) {
  for (GdrLight& l : lights) {
    if (l.type != LIGHT_ENVMAP || l.texture < 0) continue;
    const GdrTexture& t = scene.textures[l.texture];
    const int w = t.width, h = t.height;  // h >= 2: the loader pads smaller maps
    const size_t offset = tables.size();
    l.distribution_offset = static_cast<int>(offset);
    tables.resize(offset + env_table_size(w, h));
    float* table = &tables[offset];

    std::vector<double> weight(size_t(w) * h);
    double total = 0;
    for (int r = 0; r < h; ++r) {
      double sine = band_sine(r, h);
      for (int c = 0; c < w; ++c) {
        const Vec4& texel = scene.texels[size_t(t.offset) + size_t(r) * w + c];
        double lum = gdr_luminance(texel.x, texel.y, texel.z);
        weight[size_t(r) * w + c] = std::isfinite(lum) && lum > 0 ? lum * sine : 0.0;
        total += weight[size_t(r) * w + c];
      }
    }
    // A black map is never seen; sampling it by solid angle keeps the tables valid.
    if (!(total > 0)) {
      for (int r = 0; r < h; ++r)
        for (int c = 0; c < w; ++c) weight[size_t(r) * w + c] = band_sine(r, h);
    }

    // The bilinear interpolant's integral in grid units: a row's function has integral equal to
    // the sum of its weights (its intervals wrap around), a band between rows the mean of two.
    std::vector<double> row_sum(h, 0.0);
    for (int r = 0; r < h; ++r)
      for (int c = 0; c < w; ++c) row_sum[r] += weight[size_t(r) * w + c];
    std::vector<double> band_mass(h - 1);
    double z = 0;
    for (int b = 0; b + 1 < h; ++b) {
      band_mass[b] = 0.5 * (row_sum[b] + row_sum[b + 1]);
      z += band_mass[b];
    }
    write_alias(band_mass, table);
    float* sums = table + env_table_row_sums_offset(h);
    for (int r = 0; r < h; ++r) {
      sums[r] = static_cast<float>(row_sum[r] / z);
      std::vector<double> interval(w);
      for (int c = 0; c < w; ++c) {
        interval[c] = 0.5 * (weight[size_t(r) * w + c] + weight[size_t(r) * w + (c + 1) % w]);
        texels[size_t(t.offset) + size_t(r) * w + c].w = static_cast<float>(weight[size_t(r) * w + c] / z);
      }
      write_alias(interval, table + env_table_aliases_offset(w, h, r));
    }
  }
}

}  // namespace gdr
