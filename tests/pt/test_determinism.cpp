// The same seed gives the same image, bit for bit, on the same device; another seed does not.
#include <gtest/gtest.h>

#include "support/render.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

TEST(PathTracerDeterminism, SameSeedSameImage) {
  Scene scene = test::furnace_scene(0.6f, 1.0f, 12);
  RenderSettings settings;
  settings.spp = 4;
  settings.seed = 99;
  settings.max_depth = -1;
  std::vector<float> a = test::render_pt(scene, settings);
  std::vector<float> b = test::render_pt(scene, settings);
  EXPECT_EQ(a, b);
  settings.seed = 100;
  std::vector<float> c = test::render_pt(scene, settings);
  EXPECT_NE(a, c);
}

}  // namespace
}  // namespace gdr
