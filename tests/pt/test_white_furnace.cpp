// White furnace: inside a closed diffuse enclosure of albedo rho emitting Le, radiance is
// Le / (1 - rho) everywhere. The path tracer must agree within its statistical error, at every
// scene scale.
#include <gtest/gtest.h>

#include <cmath>

#include "support/render.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

class WhiteFurnace : public testing::TestWithParam<float> {};

// Seed 7, 16x16 pixels x 64 spp. The pixels (channels averaged: they share their paths) are
// independent, so the image mean has standard error sd(pixels)/16; |z| < 5 has a false-positive
// rate of 6e-7.
TEST_P(WhiteFurnace, RadianceIsLeOverOneMinusAlbedo) {
  const float albedo = 0.5f, le = 1.0f, scale = GetParam();
  Scene scene = test::furnace_scene(albedo, le, 16, scale);
  RenderSettings settings;
  settings.spp = 64;
  settings.seed = 7;
  settings.max_depth = -1;
  Stats stats;
  std::vector<float> rgb = test::render_pt(scene, settings, &stats);
  double mean = 0, sq = 0;
  for (size_t p = 0; p < rgb.size(); p += 3) {
    ASSERT_TRUE(std::isfinite(rgb[p]) && std::isfinite(rgb[p + 1]) && std::isfinite(rgb[p + 2]));
    double v = (double(rgb[p]) + rgb[p + 1] + rgb[p + 2]) / 3.0;
    mean += v;
    sq += v * v;
  }
  double n = double(rgb.size() / 3);
  mean /= n;
  double sd = std::sqrt(std::max(0.0, sq / n - mean * mean));
  double expected = le / (1.0 - albedo);
  double se = sd / std::sqrt(n);
  EXPECT_LT(std::fabs(mean - expected), 5 * se + 1e-6) << "mean " << mean << " expected " << expected << " se " << se;
  EXPECT_GT(se, 0.0);  // a noise-free image would mean the estimator did not sample anything
  EXPECT_EQ(stats.count("samples/nonfinite_rejected"), 0u);
  EXPECT_GT(stats.count("samples/paths"), 0u);  // the counters above were recorded, not absent
}

INSTANTIATE_TEST_SUITE_P(Scales, WhiteFurnace, testing::Values(1.0f, 1e-3f, 1e5f));

}  // namespace
}  // namespace gdr
