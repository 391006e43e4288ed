// The bidirectional integrator (lt, bdpt, pm and vcm) stays finite where its new paths meet the edge
// cases: every project scene, and lights that cannot emit (a zero-area triangle) beside a point
// light (a delta position, connected to the camera through one scattering vertex and, under
// bdpt, to camera vertices). The renders use a context of their own with stats, so the kernels'
// counters (rejected non-finite samples, light subpaths, connections) are read, not assumed.
#include <gtest/gtest.h>

#include <string>

#include "accel/embree_scene.h"
#include "device/devices.h"
#include "integrators/bidir/bidirectional.h"
#include "render/device_scene.h"
#include "stability/stability_checks.h"
#include "support/test_scenes.h"

namespace gdr::test {
namespace {

struct BidirRun {
  std::vector<float> rgb;
  Stats stats;
};


// `settings` on `scene` (4 spp, seed 402) on a context that records stats.
void render_bidir(const Scene& scene, int max_depth, const BidirSettings& settings, BidirRun* out) {
  Context ctx(select_device(""), &out->stats);
  EmbreeScene embree(scene, BuildQuality::Low, &out->stats);
  DeviceScene device(ctx, scene);
  Bidirectional lt(RenderInputs{ctx, scene, embree, device}, settings);
  RenderSettings s;
  s.spp = 4;
  s.seed = 402;
  s.max_depth = max_depth;
  out->rgb = lt.render(s).image.rgb_layer("");
}

const int kTechniques[] = {BIDIR_LT, BIDIR_BDPT, BIDIR_PM, BIDIR_VCM};

// Every technique in one test: the scenes' kernels are then built once.
TEST(BidirStability, ProjectScenesAreFinite) {
  int scenes = for_each_project_scene(24, [](const std::string& path, const Scene& scene) {
    for (int technique : kTechniques) {
      const std::string what = path + " (" + bidir_technique_name(technique) + ")";
      BidirRun r;
      render_bidir(scene, scene.max_depth > 0 ? scene.max_depth : 16, bidir_settings(technique, IntegratorParams{}), &r);
      EXPECT_TRUE(all_finite(r.rgb)) << what;
      EXPECT_EQ(r.stats.count("samples/nonfinite_rejected"), 0u) << what;
      EXPECT_GT(r.stats.count("bidir/light_subpaths"), 0u) << what;
      if (technique != BIDIR_PM) EXPECT_GT(r.stats.count("bidir/camera_connections"), 0u) << what;
      if (technique != BIDIR_LT) EXPECT_GT(r.stats.count("bidir/light_vertices"), 0u) << what;
      if (technique == BIDIR_BDPT || technique == BIDIR_VCM) {
        EXPECT_GT(r.stats.count("bidir/connections"), 0u) << what;
        EXPECT_GT(r.stats.count("bidir/light_connections"), 0u) << what;
      }
      if (technique == BIDIR_PM || technique == BIDIR_VCM) EXPECT_GT(r.stats.count("bidir/merges"), 0u) << what;
      double sum = 0;
      for (float v : r.rgb) sum += v;
      EXPECT_GT(sum, 0.0) << what << " rendered black";
    }
  });
  EXPECT_GE(scenes, 5);
}

// A diffuse wall lit by a point light and by a degenerate (zero-area) emitting triangle: the
// triangle starts no light subpath, the point light's do, and every pixel is finite.
TEST(BidirStability, ZeroAreaLightAndPointLight) {
  Scene scene = point_light_beside_zero_area_emitter();
  for (int technique : kTechniques) {
    BidirRun r;
    render_bidir(scene, -1, bidir_settings(technique, IntegratorParams{}), &r);
    EXPECT_TRUE(all_finite(r.rgb)) << bidir_technique_name(technique);
    EXPECT_EQ(r.stats.count("samples/nonfinite_rejected"), 0u) << bidir_technique_name(technique);
    double sum = 0;
    for (float v : r.rgb) sum += v;
    EXPECT_GT(sum, 0.0) << bidir_technique_name(technique);
    // The selection gives the triangle no power (it has no area), so every subpath of the 4
    // passes of 16 x 16 comes from the point light, whose emission never fails.
    EXPECT_EQ(r.stats.count("bidir/light_subpaths"), uint64_t(16 * 16 * 4)) << bidir_technique_name(technique);
  }
}

}  // namespace
}  // namespace gdr::test
