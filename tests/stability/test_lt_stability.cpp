// The light tracer stays finite where its new paths meet the edge cases: every project scene,
// and lights that cannot emit (a zero-area triangle) beside a point light (a delta position
// connected to the camera through one scattering vertex). The renders use a context of their
// own with stats, so the kernels' counters (rejected non-finite samples, light subpaths,
// camera connections) are read, not assumed.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "accel/embree_scene.h"
#include "device/devices.h"
#include "integrators/bidir/light_tracer.h"
#include "render/device_scene.h"
#include "scene/load_scene.h"
#include "stability/stability_checks.h"
#include "support/test_scenes.h"

namespace gdr::test {
namespace {

struct LtRun {
  std::vector<float> rgb;
  Stats stats;
};

// lt on `scene` (4 spp, seed 402) on a context that records stats.
void render_lt(const Scene& scene, int max_depth, LtRun* out) {
  Context ctx(select_device(""), &out->stats);
  EmbreeScene embree(scene, BuildQuality::Low, &out->stats);
  DeviceScene device(ctx, scene);
  LightTracer lt(RenderInputs{ctx, scene, embree, device}, LtSettings{});
  RenderSettings s;
  s.spp = 4;
  s.seed = 402;
  s.max_depth = max_depth;
  out->rgb = lt.render(s).image.rgb_layer("");
}

TEST(LightTracerStability, ProjectScenesAreFinite) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(GDR_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".xml") continue;
    ++scenes;
    Scene scene = load_scene(entry.path().string());
    int w = 24, h = std::max(1, w * scene.camera.height / std::max(1, scene.camera.width));
    scene.camera.width = w;
    scene.camera.height = h;
    LtRun r;
    render_lt(scene, scene.max_depth > 0 ? scene.max_depth : 16, &r);
    EXPECT_TRUE(all_finite(r.rgb)) << entry.path();
    EXPECT_EQ(r.stats.count("samples/nonfinite_rejected"), 0u) << entry.path();
    EXPECT_GT(r.stats.count("lt/light_subpaths"), 0u) << entry.path();
    EXPECT_GT(r.stats.count("lt/camera_connections"), 0u) << entry.path();
    double sum = 0;
    for (float v : r.rgb) sum += v;
    EXPECT_GT(sum, 0.0) << entry.path() << " rendered black";
  }
  EXPECT_GE(scenes, 5);
}

// A diffuse wall lit by a point light and by a degenerate (zero-area) emitting triangle: the
// triangle starts no light subpath, the point light's do, and every pixel is finite.
TEST(LightTracerStability, ZeroAreaLightAndPointLight) {
  SceneBuilder b;
  GdrMaterial m{};
  m.type = BSDF_DIFFUSE;
  m.reflectance_texture = -1;
  m.coating_table = -1;
  m.reflectance[0] = m.reflectance[1] = m.reflectance[2] = 0.5f;
  int wall = b.material(m, "wall");
  b.shape(quad_mesh({-5, -5, 10}, {-5, 5, 10}, {5, 5, 10}, {5, -5, 10}), wall, 0.0f, "wall");
  b.shape(triangle_mesh({0, 0, 8}, {1, 1, 8}, {2, 2, 8}), wall, 10.0f, "zero-area light");
  GdrLight point{};
  point.type = LIGHT_POINT;
  point.texture = -1;
  point.triangle = -1;
  point.radiance[0] = point.radiance[1] = point.radiance[2] = 20.0f;
  point.position[2] = 5.0f;
  b.scene().lights.push_back(point);
  Scene scene = b.finish(camera_looking_z(0, 0, 0, 40.0f, 16));
  LtRun r;
  render_lt(scene, -1, &r);
  EXPECT_TRUE(all_finite(r.rgb));
  EXPECT_EQ(r.stats.count("samples/nonfinite_rejected"), 0u);
  double sum = 0;
  for (float v : r.rgb) sum += v;
  EXPECT_GT(sum, 0.0);
  // The selection gives the triangle no power (it has no area), so every subpath of the 4 passes
  // of 16 x 16 comes from the point light, whose emission never fails.
  EXPECT_EQ(r.stats.count("lt/light_subpaths"), uint64_t(16 * 16 * 4));
}

}  // namespace
}  // namespace gdr::test
