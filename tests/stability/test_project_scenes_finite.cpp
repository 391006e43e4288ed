// Every project scene (scenes/*.xml) renders at a small resolution with every pixel finite and
// no sample rejected as NaN or Inf.
#include <gtest/gtest.h>

#include <string>

#include "stability/stability_checks.h"

namespace gdr::test {
namespace {

TEST(ProjectScenesFinite, NoNonFiniteSamples) {
  int scenes = for_each_project_scene(24, [](const std::string& path, const Scene& scene) {
    Rendered r = render_checked(scene, 401, 4, scene.max_depth > 0 ? scene.max_depth : 16);
    EXPECT_TRUE(all_finite(r.rgb)) << path;
    EXPECT_EQ(r.nonfinite, 0u) << path;
    double sum = 0;
    for (float v : r.rgb) sum += v;
    EXPECT_GT(sum, 0.0) << path << " rendered black";
  });
  EXPECT_GE(scenes, 5);
}

}  // namespace
}  // namespace gdr::test
