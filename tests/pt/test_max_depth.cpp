// max_depth as Mitsuba defines it, for every integrator of the registry: 0 renders nothing (not
// even emitters seen directly), 1 only the emitters seen directly, and deeper paths add light.
#include <gtest/gtest.h>

#include "integrators/registry.h"
#include "scene/load_scene.h"
#include "support/render.h"
#include "support/source_scene.h"

namespace gdr {
namespace {

double image_sum(const std::vector<float>& rgb) {
  double sum = 0;
  for (float v : rgb) sum += v;
  return sum;
}

TEST(MaxDepth, ZeroIsBlackOneIsEmittersOnly) {
  LoadOptions o;
  o.defines = {{"res", "16"}};
  Scene scene = load_scene(test::source_scene("cornell-box.xml"), o);
  test::SceneOnDevice on_device(scene);
  for (const IntegratorEntry& e : integrator_registry()) {
    SCOPED_TRACE(e.name);
    IntegratorParams p;
    if (e.gradient) p.set("recon", "none");
    std::unique_ptr<Integrator> integrator = e.make(on_device.inputs(), p);
    double sums[3];
    for (int depth = 0; depth < 3; ++depth) {
      RenderSettings s;
      s.spp = 2;
      s.max_depth = depth;
      sums[depth] = image_sum(integrator->render(s).image.rgb_layer(""));
    }
    EXPECT_EQ(sums[0], 0.0);
    EXPECT_GT(sums[1], 0.0);
    EXPECT_GT(sums[2], 1.2 * sums[1]);  // direct light on the walls adds to the emitter seen
  }
}

}  // namespace
}  // namespace gdr
