// Bidirectional path tracing (`bdpt`) converges to the path tracer's image, with either
// heuristic, on a diffuse, a glossy and a specular scene; each strategy rendered alone gives the
// paths of its length; the white furnace holds. The comparisons are per 4 x 4 block (and whole
// image) Welch t-tests over 16 independent runs of each (bdpt seeds 1..16, pt seeds 101..116),
// each at a family false-positive rate of 1e-3 (support/agreement.h). What bdpt shares with the
// other techniques (max_depth 1 and 0, same seed same image) is in test_bidir_techniques.cpp.
#include <gtest/gtest.h>

#include "integrators/bidir/bidirectional.h"
#include "support/agreement.h"
#include "support/render.h"
#include "support/test_scenes.h"
#include "util/error.h"

namespace gdr {
namespace {

constexpr int kRuns = 16;

BidirSettings bdpt_with(const std::map<std::string, std::string>& params) {
  return bdpt_settings(IntegratorParams(params));
}

void expect_agrees_with_pt(const Scene& scene, const std::string& name, const BidirSettings& bdpt_settings,
                           int spp, int max_depth) {
  test::SceneOnDevice on_device(scene);
  Bidirectional bdpt(on_device.inputs(), bdpt_settings);
  PathTracer pt(on_device.inputs(), PtSettings{});
  const int w = scene.camera.width, h = scene.camera.height;
  test::expect_blocks_agree(test::block_means(bdpt, w, h, spp, max_depth, 1, kRuns),
                            test::block_means(pt, w, h, spp, max_depth, 101, kRuns), name, "bdpt", "pt");
}

TEST(Bdpt, CornellBoxAgreesWithPt) {
  expect_agrees_with_pt(test::project_scene("cornell-box.xml", 24), "cornell-box.xml", bdpt_with({}), 8, 6);
}

TEST(Bdpt, BalanceHeuristicAgreesWithPt) {
  expect_agrees_with_pt(test::project_scene("cornell-box.xml", 24), "cornell-box.xml (balance)",
                        bdpt_with({{"mis", "balance"}}), 8, 6);
}

// The plates at least 0.2 rough, as for lt: the smoother ones make pt's light-sampled runs too
// heavy-tailed for a t-test over 16 runs (tests/pt/test_strategies.cpp).
TEST(Bdpt, GlossyPlatesAgreeWithPt) {
  Scene scene = test::project_scene("glossy-plates.xml", 32);
  for (GdrMaterial& m : scene.materials) {
    if (m.type == BSDF_ROUGH_PLASTIC) m.alpha_u = m.alpha_v = std::max(m.alpha_u, 0.2f);
  }
  expect_agrees_with_pt(scene, "glossy-plates.xml (plates at least 0.2 rough)", bdpt_with({}), 8, 6);
}

// A glass sphere and a mirror: delta vertices that no connection can end at, caustics that only
// the light subpaths reach through them.
TEST(Bdpt, CausticsBoxAgreesWithPt) {
  expect_agrees_with_pt(test::project_scene("cornell-box-caustics.xml", 24), "cornell-box-caustics.xml", bdpt_with({}),
                        8, 6);
}

// Connections evaluate the light vertex in importance transport, with the shading-normal
// correction (support/test_scenes.h: the coarse smooth sphere).
TEST(Bdpt, ShadingNormalsAgreeWithPt) {
  expect_agrees_with_pt(test::coarse_smooth_sphere_scene(), "coarse smooth sphere", bdpt_with({}), 32, 4);
}

// A strategy alone, unweighted, estimates all paths of its length s + t - 1 (on the diffuse box
// every strategy can sample every path): pt's image at max_depth k minus its image at k - 1 with
// the same seed is exactly pt's estimate of those paths.
TEST(Bdpt, EachStrategyAloneGivesThePathsOfItsLength) {
  Scene scene = test::project_scene("cornell-box.xml", 24);
  test::SceneOnDevice on_device(scene);
  const int w = scene.camera.width, h = scene.camera.height, k = 3;
  PathTracer pt(on_device.inputs(), PtSettings{});
  auto longer = test::block_means(pt, w, h, 8, k, 101, kRuns), shorter = test::block_means(pt, w, h, 8, k - 1, 101, kRuns);
  for (int r = 0; r < kRuns; ++r)
    for (size_t b = 0; b < longer[r].size(); ++b) longer[r][b] -= shorter[r][b];
  for (int s = 0; s <= k; ++s) {
    int t = k + 1 - s;
    std::string st = std::to_string(s) + "," + std::to_string(t);
    Bidirectional one(on_device.inputs(), bdpt_with({{"strategy", st}}));
    test::expect_blocks_agree(test::block_means(one, w, h, 8, k, 1, kRuns), longer,
                              "cornell-box.xml, strategy " + st, "bdpt", "pt (paths of 3 segments)");
  }
}

// The white furnace: a closed diffuse cube of albedo 0.5 whose walls emit 1 shows 1 / (1 - 0.5)
// = 2 everywhere; paths longer than the store's bound (16 segments) would add 2 * 0.5^16.
TEST(Bdpt, WhiteFurnace) {
  Scene scene = test::furnace_scene(0.5f, 1.0f, 8);
  test::SceneOnDevice on_device(scene);
  Bidirectional bdpt(on_device.inputs(), bdpt_with({}));
  RenderSettings s;
  s.spp = 64;
  s.seed = 4;
  s.max_depth = -1;
  test::expect_furnace_mean(bdpt.render(s).image.rgb_layer(""), 2.0, 2.0 * std::pow(0.5, 16));
}

TEST(Bdpt, StrategyParameterIsChecked) {
  for (const char* bad : {"1,1", "0,1", "2", "a,b", "2,-1", "-1,3", "2,2,2"}) {
    EXPECT_THROW(bdpt_with({{"strategy", bad}}), Error) << bad;
  }
  BidirSettings s = bdpt_with({{"strategy", "2,1"}});
  EXPECT_EQ(s.options.strategy_s, 2);
  EXPECT_EQ(s.options.strategy_t, 1);
  EXPECT_THROW(bdpt_with({{"mis", "cubic"}}), Error);
}

}  // namespace
}  // namespace gdr
