// The light tracer (`lt`) converges to the path tracer's image: per 4 x 4 pixel block, Welch's
// t-test compares the mean luminance of K independent runs of each (seeds 1..K for lt, 101..100+K
// for pt), Šidák-corrected over the blocks of a scene so that each scene's test has a
// false-positive rate of 1e-3 (support/agreement.h); the white furnace holds. What lt shares with
// the other techniques (max_depth 1 and 0, same seed same image) is in test_bidir_techniques.cpp.
#include <gtest/gtest.h>

#include <algorithm>

#include "integrators/bidir/bidirectional.h"
#include "scene/load_scene.h"
#include "support/render.h"
#include "support/agreement.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

constexpr int kTracerRuns = 16;

void expect_agrees_with_pt(const Scene& scene, const std::string& name, int lt_spp, int pt_spp, int max_depth) {
  test::SceneOnDevice on_device(scene);
  Bidirectional lt(on_device.inputs(), BidirSettings{});
  PathTracer pt(on_device.inputs(), PtSettings{});
  const int w = scene.camera.width, h = scene.camera.height;
  test::expect_blocks_agree(test::block_means(lt, w, h, lt_spp, max_depth, 1, kTracerRuns),
                            test::block_means(pt, w, h, pt_spp, max_depth, 101, kTracerRuns), name, "lt", "pt");
}

TEST(LightTracer, CornellBoxAgreesWithPt) {
  Scene scene = test::project_scene("cornell-box.xml", 24);
  expect_agrees_with_pt(scene, "cornell-box.xml", 16, 16, 6);
}

// Glossy plates under small spherical lights; the plates are made at least 0.2 rough, as the
// path tracer's strategy test does for its light-only technique (a light subpath reaches the
// camera from a smoother plate too rarely for a t-test over a few runs to be valid).
TEST(LightTracer, GlossyPlatesAgreeWithPt) {
  Scene scene = load_scene(test::source_scene("glossy-plates.xml"));
  for (GdrMaterial& m : scene.materials) {
    if (m.type == BSDF_ROUGH_PLASTIC) m.alpha_u = m.alpha_v = std::max(m.alpha_u, 0.2f);
  }
  expect_agrees_with_pt(test::small_film(scene, 32), "glossy-plates.xml (plates at least 0.2 rough)", 16, 16, 6);
}

// Where the shading normals of a coarse smooth sphere differ from its facets' by up to ~40
// degrees, importance transport needs the shading-normal correction to give pt's image.
TEST(LightTracer, ShadingNormalsAgreeWithPt) {
  Scene scene = test::coarse_smooth_sphere_scene();
  ASSERT_TRUE(scene.shapes[0].flags & SHAPE_HAS_NORMALS);
  expect_agrees_with_pt(scene, "coarse smooth sphere", 64, 64, 4);
}

// The white furnace: inside a closed diffuse cube of albedo a whose walls emit le, every pixel
// sees le / (1 - a); light subpaths of every length add up to it (unbounded depth, Russian
// roulette), and every pixel is finite.
TEST(LightTracer, WhiteFurnace) {
  Scene scene = test::furnace_scene(0.5f, 1.0f, 8);
  test::SceneOnDevice on_device(scene);
  Bidirectional lt(on_device.inputs(), BidirSettings{});
  RenderSettings s;
  s.spp = 256;
  s.seed = 4;
  s.max_depth = -1;
  test::expect_furnace_mean(lt.render(s).image.rgb_layer(""), 2.0);
}

}  // namespace
}  // namespace gdr
