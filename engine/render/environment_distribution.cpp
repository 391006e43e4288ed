#include "render/environment_distribution.h"

#include <cmath>

#include "shared/color.h"
#include "shared/environment_table.h"

namespace gdr {
namespace {

// Normalised cdf of `weights` (uniform when they sum to zero) into out[0 .. weights.size()].
void write_cdf(const std::vector<double>& weights, float* out) {
  double total = 0;
  for (double w : weights) total += w;
  double acc = 0;
  out[0] = 0.0f;
  for (size_t i = 0; i < weights.size(); ++i) {
    acc += total > 0 ? weights[i] / total : 1.0 / weights.size();
    out[i + 1] = i + 1 == weights.size() ? 1.0f : static_cast<float>(acc);
  }
}

}  // namespace

void build_environment_tables(const Scene& scene, std::vector<GdrLight>& lights, std::vector<float>& tables) {
  constexpr double pi = 3.14159265358979323846;
  for (GdrLight& l : lights) {
    if (l.type != LIGHT_ENVMAP || l.texture < 0) continue;
    const GdrTexture& t = scene.textures[l.texture];
    const int w = t.width, h = t.height;
    const size_t offset = tables.size();
    l.distribution_offset = static_cast<int>(offset);
    tables.resize(offset + env_table_size(w, h));
    std::vector<double> row_weight(h);
    for (int r = 0; r < h; ++r) {
      double sin_theta = std::sin(pi * (r + 0.5) / h);
      std::vector<double> weight(w);
      for (int c = 0; c < w; ++c) {
        const Vec4& texel = scene.texels[size_t(t.offset) + size_t(r) * w + c];
        double lum = gdr_luminance(texel.x, texel.y, texel.z);
        weight[c] = std::isfinite(lum) && lum > 0 ? lum * sin_theta : 0.0;
        row_weight[r] += weight[c];
      }
      write_cdf(weight, &tables[offset + env_table_columns_offset(w, h, r)]);
    }
    write_cdf(row_weight, &tables[offset]);
  }
}

}  // namespace gdr
