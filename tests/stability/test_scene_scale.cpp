// Radiance does not depend on the unit of length: the project's Cornell boxes scaled so that
// their extent is 1e-3 or 1e5 (about 1.8e-6x and 180x the millimetre originals; the furnace
// test covers the analytic case) must render the same image as the originals. Self-intersection
// at small scales or lost precision at large ones shows as a shifted mean.
#include <gtest/gtest.h>

#include <string>

#include "scene/load_scene.h"
#include "stability/stability_checks.h"
#include "support/source_scene.h"
#include "support/test_scenes.h"

namespace gdr::test {
namespace {

struct ScaleCase {
  const char* scene;
  float extent;
};

Scene load_small(const std::string& name) {
  LoadOptions options;
  options.defines = {{"res", "32"}};
  return load_scene(source_scene(name), options);
}

class SceneScale : public testing::TestWithParam<ScaleCase> {};

// Seeds 301 (original) and 302 (scaled), 32x32 pixels x 16 spp each, max depth 8. The per-pixel
// differences of two independent renders are independent with mean 0 when the expectations
// agree, so |z| < 5 on their mean has a false-positive rate of 5.7e-7 per case.
TEST_P(SceneScale, ImageMatchesTheOriginal) {
  const ScaleCase c = GetParam();
  Scene original = load_small(c.scene);
  Scene scaled = original;
  float extent = 0;
  for (int a = 0; a < 3; ++a) extent = std::max(extent, original.bounds_max[a] - original.bounds_min[a]);
  scale_scene(scaled, c.extent / extent);
  Rendered a = render_checked(original, 301, 16, 8), b = render_checked(scaled, 302, 16, 8);
  ASSERT_TRUE(all_finite(b.rgb));
  EXPECT_EQ(b.nonfinite, 0u);
  EXPECT_EQ(a.nonfinite, 0u);
  double mean = 0, se = 0;
  double z = mean_z(b.rgb, std::vector<double>(a.rgb.begin(), a.rgb.end()), &mean, &se);
  double ref = 0;
  for (float v : a.rgb) ref += v / double(a.rgb.size());
  EXPECT_LT(std::fabs(z), 5.0) << c.scene << " at extent " << c.extent << ": mean difference " << mean
                               << " (original mean " << ref << ", se " << se << ")";
}

INSTANTIATE_TEST_SUITE_P(Extents, SceneScale,
                         testing::Values(ScaleCase{"cornell-box.xml", 1e-3f}, ScaleCase{"cornell-box.xml", 1e5f},
                                         ScaleCase{"cornell-box-caustics.xml", 1e-3f},
                                         ScaleCase{"cornell-box-caustics.xml", 1e5f}),
                         [](const testing::TestParamInfo<ScaleCase>& info) {
                           std::string name = info.param.scene;
                           name = name.substr(0, name.find('.'));
                           for (char& ch : name) ch = ch == '-' ? '_' : ch;
                           return name + (info.param.extent < 1 ? "_tiny" : "_huge");
                         });

}  // namespace
}  // namespace gdr::test
