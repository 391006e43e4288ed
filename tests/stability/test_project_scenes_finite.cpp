// Every project scene (scenes/*.xml) renders at a small resolution with every pixel finite and
// no sample rejected as NaN or Inf.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene/load_scene.h"
#include "stability/stability_checks.h"

namespace gdr::test {
namespace {

TEST(ProjectScenesFinite, NoNonFiniteSamples) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(GDR_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".xml") continue;
    ++scenes;
    Scene scene = load_scene(entry.path().string());
    // A small film of the scene's aspect (the field of view is unchanged).
    int w = 24, h = std::max(1, w * scene.camera.height / std::max(1, scene.camera.width));
    scene.camera.width = w;
    scene.camera.height = h;
    Rendered r = render_checked(scene, 401, 4, scene.max_depth > 0 ? scene.max_depth : 16);
    EXPECT_TRUE(all_finite(r.rgb)) << entry.path();
    EXPECT_EQ(r.nonfinite, 0u) << entry.path();
    double sum = 0;
    for (float v : r.rgb) sum += v;
    EXPECT_GT(sum, 0.0) << entry.path() << " rendered black";
  }
  EXPECT_GE(scenes, 5);
}

}  // namespace
}  // namespace gdr::test
