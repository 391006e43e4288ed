// The Metropolis integrators (mlt, gmlt) stay finite on every project scene (glass, mirrors,
// rough metals, an environment map) and beside a delta light with a degenerate emitter (a
// zero-area triangle and a point light: no path through the pinhole sees a point light, so
// mlt's strategies that end on it are the connections, gmlt's the next-event estimation): every
// pixel finite, no sample rejected as NaN or Inf, something rendered, and the chains moved.
// Renders of 24 pixels wide (16 for the light case), 1024 chains, 4 passes, seed 403, on a
// context of their own with stats.
#include <gtest/gtest.h>

#include <string>

#include "accel/embree_scene.h"
#include "device/devices.h"
#include "integrators/registry.h"
#include "render/device_scene.h"
#include "stability/stability_checks.h"
#include "support/test_scenes.h"

namespace gdr::test {
namespace {

void expect_stable(const Scene& scene, int max_depth, const std::string& what) {
  for (const char* name : {"mlt", "gmlt"}) {
    Stats stats;
    Context ctx(select_device(""), &stats);
    EmbreeScene embree(scene, BuildQuality::Low, &stats);
    DeviceScene device(ctx, scene);
    IntegratorParams params(std::map<std::string, std::string>{{"chains", "1024"}, {"bootstrap", "16384"}});
    std::unique_ptr<Integrator> integrator = find_integrator(name).make(RenderInputs{ctx, scene, embree, device}, params);
    RenderSettings s;
    s.spp = 4;
    s.seed = 403;
    s.max_depth = max_depth;
    std::vector<float> rgb = integrator->render(s).image.rgb_layer("");
    EXPECT_TRUE(all_finite(rgb)) << what << " (" << name << ")";
    EXPECT_EQ(stats.count("samples/nonfinite_rejected"), 0u) << what << " (" << name << ")";
    EXPECT_GT(stats.count("mlt/small_steps_accepted") + stats.count("mlt/large_steps_accepted"), 0u)
        << what << " (" << name << "): no chain moved";
    double sum = 0;
    for (float v : rgb) sum += v;
    EXPECT_GT(sum, 0.0) << what << " (" << name << ") rendered black";
  }
}

TEST(MetropolisStability, ProjectScenesAreFinite) {
  int scenes = for_each_project_scene(24, [](const std::string& path, const Scene& scene) {
    expect_stable(scene, scene.max_depth > 0 ? scene.max_depth : 16, path);
  });
  EXPECT_GE(scenes, 5);
}

TEST(MetropolisStability, ZeroAreaLightAndPointLight) {
  expect_stable(point_light_beside_zero_area_emitter(), -1, "point light and zero-area emitter");
}

}  // namespace
}  // namespace gdr::test
