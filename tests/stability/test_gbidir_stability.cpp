// The gradient-domain bidirectional integrators (gbdpt, gpm, gvcm) stay finite on every project
// scene (glass, mirrors, rough metals, an environment map with a sun) and beside a delta light with
// a degenerate emitter (a zero-area triangle and a point light: gbdpt's and gvcm's offsets'
// connections end on both, gpm's and gvcm's photons and gbdpt's light-traced vertices are shifted
// from both; gbdpt and gvcm also with the manifold shift): every pixel of every layer finite, no
// sample rejected as NaN or Inf, something rendered, connections, merges or light-tracing offsets
// made. Renders of 24 pixels wide, 4
// samples a pixel, seed 404, on a context of their own with stats.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "accel/embree_scene.h"
#include "device/devices.h"
#include "integrators/registry.h"
#include "render/device_scene.h"
#include "stability/stability_checks.h"
#include "support/test_scenes.h"

namespace gdr::test {
namespace {

// `integrator` renders `scene`; `made` counts what it must have done (connections, merges).
void expect_stable(const char* integrator, std::vector<const char*> made, const Scene& scene, int max_depth,
                   const std::string& what, const IntegratorParams& params = {}) {
  Stats stats;
  Context ctx(select_device(""), &stats);
  EmbreeScene embree(scene, BuildQuality::Low, &stats);
  DeviceScene device(ctx, scene);
  std::unique_ptr<Integrator> gradient =
      find_integrator(integrator).make(RenderInputs{ctx, scene, embree, device}, params);
  RenderSettings s;
  s.spp = 4;
  s.seed = 404;
  s.max_depth = max_depth;
  RenderResult r = gradient->render(s);
  for (const char* layer : {"", "primal", "dx", "dy"}) {
    EXPECT_TRUE(all_finite(r.image.rgb_layer(layer))) << what << ": layer '" << layer << "'";
  }
  EXPECT_EQ(stats.count("samples/nonfinite_rejected"), 0u) << what;
  for (const char* m : made) EXPECT_GT(stats.count(m), 0u) << what << ": " << m;
  double sum = 0;
  for (float v : r.image.rgb_layer("primal")) sum += v;
  EXPECT_GT(sum, 0.0) << what << " rendered black";
}

// Every project scene (at least five), at its own max_depth (16 where it has none).
void expect_project_scenes_stable(const char* integrator, const char* made, const IntegratorParams& params = {}) {
  int scenes = for_each_project_scene(24, [&](const std::string& path, const Scene& scene) {
    expect_stable(integrator, {made}, scene, scene.max_depth > 0 ? scene.max_depth : 16, path, params);
  });
  EXPECT_GE(scenes, 5);
}

// With the manifold shift: the camera subpaths' offsets walk the glass and mirror chains.
const IntegratorParams& manifold_shift() {
  static const IntegratorParams p(std::map<std::string, std::string>{{"shift", "manifold"}});
  return p;
}

TEST(GbdptStability, ProjectScenesAreFinite) { expect_project_scenes_stable("gbdpt", "gbdpt/connections"); }
TEST(GbdptStability, ProjectScenesAreFiniteWithManifoldShift) {
  expect_project_scenes_stable("gbdpt", "gbdpt/connections", manifold_shift());
}

// Light tracing's vertices lit by the point light are shifted from it.
TEST(GbdptStability, ZeroAreaLightAndPointLight) {
  expect_stable("gbdpt", {"gbdpt/connections", "gbdpt/light_tracing_offsets"}, point_light_beside_zero_area_emitter(),
                -1, "point light and zero-area emitter");
}

TEST(GpmStability, ProjectScenesAreFinite) { expect_project_scenes_stable("gpm", "gpm/merges"); }
TEST(GpmStability, ZeroAreaLightAndPointLight) {
  expect_stable("gpm", {"gpm/merges"}, point_light_beside_zero_area_emitter(), -1,
                "point light and zero-area emitter");
}

TEST(GvcmStability, ProjectScenesAreFinite) { expect_project_scenes_stable("gvcm", "gpm/merges"); }
TEST(GvcmStability, ProjectScenesAreFiniteWithManifoldShift) {
  expect_project_scenes_stable("gvcm", "gpm/merges", manifold_shift());
}
TEST(GvcmStability, ZeroAreaLightAndPointLight) {
  expect_stable("gvcm", {"gbdpt/connections", "gpm/merges"}, point_light_beside_zero_area_emitter(), -1,
                "point light and zero-area emitter");
}

}  // namespace
}  // namespace gdr::test
