#include "render/environment_distribution.h"

#include <cmath>

#include "shared/color.h"
#include "shared/environment_table.h"

namespace gdr {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Normalised cdf of `masses` (uniform when they sum to zero) into out[0 .. masses.size()].
void write_cdf(const std::vector<double>& masses, float* out) {
  double total = 0;
  for (double m : masses) total += m;
  double acc = 0;
  out[0] = 0.0f;
  for (size_t i = 0; i < masses.size(); ++i) {
    acc += total > 0 ? masses[i] / total : 1.0 / masses.size();
    out[i + 1] = i + 1 == masses.size() ? 1.0f : static_cast<float>(acc);
  }
}

// The guide of a cdf over n intervals (shared/environment_table.h): entry j is the interval with
// cdf[i] <= j / K < cdf[i + 1], found by the kernels' comparison (the first i with
// cdf[i + 1] > u, the last interval when none).
void write_guide(const float* cdf, int n, float* out) {
  const int k = env_table_guide_buckets(n);
  int i = 0;
  for (int j = 0; j <= k; ++j) {
    const float u = static_cast<float>(j) / static_cast<float>(k);
    while (i < n - 1 && cdf[i + 1] <= u) ++i;
    out[j] = static_cast<float>(i);
  }
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

void build_environment_tables(const Scene& scene, std::vector<GdrLight>& lights, std::vector<float>& tables) {
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
    write_cdf(band_mass, table);
    float* sums = table + env_table_row_sums_offset(h);
    for (int r = 0; r < h; ++r) {
      sums[r] = static_cast<float>(row_sum[r] / z);
      std::vector<double> interval(w);
      float* f = table + env_table_weights_offset(w, h, r);
      for (int c = 0; c < w; ++c) {
        interval[c] = 0.5 * (weight[size_t(r) * w + c] + weight[size_t(r) * w + (c + 1) % w]);
        f[c] = static_cast<float>(weight[size_t(r) * w + c] / z);
      }
      write_cdf(interval, table + env_table_columns_offset(w, h, r));
      write_guide(table + env_table_columns_offset(w, h, r), w, table + env_table_column_guide_offset(w, h, r));
    }
    write_guide(table, h - 1, table + env_table_band_guide_offset(w, h));
  }
}

}  // namespace gdr
