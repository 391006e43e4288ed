// G-PT's per-material queues (render/wavefront/material_queues.h). Routed (GptSettings::
// route_materials, a GPU's default), the groups' shade step runs one kernel per BSDF type the
// scene has, gpt_shade_<type>, over the groups whose base hit that type, and none for the types it
// lacks; unrouted (a CPU device's default), the program's gpt_shade shades every type in one
// queue. The images do not depend on it: each group's step is its own, whatever order the queues
// take the groups in. On the glass box (diffuse, dielectric: gpt and gbdpt) and the environment
// scene (diffuse, rough conductor, rough plastic: gpt), 48 px, 2 spp, seed 7.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "integrators/gbidir/gradient_bidirectional.h"
#include "integrators/gpt/gradient_path_tracer.h"
#include "scene/scene_features.h"
#include "support/agreement.h"
#include "support/render.h"

namespace gdr {
namespace {

struct Rendered {
  GradientImages images;
  Stats stats;
};

void render(const Scene& scene, bool bidirectional, bool routed, Rendered& out) {
  test::SceneOnCountingDevice on_device(scene, &out.stats);
  RenderSettings s;
  s.spp = 2;
  s.seed = 7;
  GptSettings gs;
  gs.route_materials = routed;
  out.images = bidirectional ? GradientBidirectional(on_device.inputs(), gs).render_gradients(s)
                             : GradientPathTracer(on_device.inputs(), gs).render_gradients(s);
}

void expect_same_images_routed(const std::string& file, bool bidirectional, int expected_types) {
  const Scene scene = test::project_scene(file, 48);
  Rendered routed, unrouted;
  render(scene, bidirectional, true, routed);
  render(scene, bidirectional, false, unrouted);

  int types = 0;
  for (int t = 0; t < BSDF_TYPE_COUNT; ++t) {
    const std::string name = std::string("kernel_items/gpt_shade_") + bsdf_type_name(t);
    if (scene.features.bsdf[t]) {
      ++types;
      EXPECT_GT(routed.stats.count(name), 0u) << file << ": " << name << " never ran";
    } else {
      EXPECT_EQ(routed.stats.count(name), 0u) << file << ": " << name << " ran";
    }
    EXPECT_EQ(unrouted.stats.count(name), 0u) << file << ": " << name << " ran unrouted";
  }
  EXPECT_EQ(types, expected_types) << file;
  EXPECT_GT(routed.stats.count("kernel_items/gpt_route"), 0u) << file;
  EXPECT_EQ(routed.stats.count("kernel_items/gpt_shade"), 0u) << file;
  EXPECT_EQ(unrouted.stats.count("kernel_items/gpt_route"), 0u) << file;
  EXPECT_GT(unrouted.stats.count("kernel_items/gpt_shade"), 0u) << file;

  const GradientImages& a = routed.images;
  const GradientImages& b = unrouted.images;
  EXPECT_GT(*std::max_element(a.primal.begin(), a.primal.end()), 0.0f) << file;
  EXPECT_EQ(a.primal, b.primal) << file;
  EXPECT_EQ(a.dx, b.dx) << file;
  EXPECT_EQ(a.dy, b.dy) << file;
  EXPECT_EQ(a.direct, b.direct) << file;
}

TEST(GptMaterialQueues, GlassBoxRoutedAsUnrouted) { expect_same_images_routed("glass-box.xml", false, 2); }
TEST(GptMaterialQueues, EnvironmentSceneRoutedAsUnrouted) { expect_same_images_routed("environment.xml", false, 3); }
TEST(GptMaterialQueues, GbdptGlassBoxRoutedAsUnrouted) { expect_same_images_routed("glass-box.xml", true, 2); }

}  // namespace
}  // namespace gdr
