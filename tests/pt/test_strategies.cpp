// BSDF-only and light-only sampling converge to the same image as their MIS combination.
// Each strategy renders K independent runs (seeds 1..K); per 4x4 pixel block, Welch's t-test
// compares the run means of the luminance. Šidák-corrected so the whole test has a
// false-positive rate of 1e-3.
#include <gtest/gtest.h>

#include <algorithm>

#include "scene/load_scene.h"
#include "support/envmap_scene.h"
#include "support/render.h"
#include "support/source_scene.h"
#include "support/statistics.h"

namespace gdr {
namespace {

constexpr int kStrategyWidth = 24, kBlock = 4, kStrategyRuns = 24, kStrategySpp = 4;

// runs[k][block]: the block's mean luminance in run k.
std::vector<std::vector<double>> block_means(test::SceneOnDevice& scene, int width, int height, int strategy,
                                             int spp) {
  PtSettings pt;
  pt.strategy = strategy;
  PathTracer tracer(scene.inputs(), pt);
  std::vector<std::vector<double>> runs;
  for (int k = 0; k < kStrategyRuns; ++k) {
    RenderSettings s;
    s.spp = spp;
    s.seed = 1 + k;
    s.max_depth = 6;
    std::vector<float> rgb = tracer.render(s).image.rgb_layer("");
    std::vector<double> blocks((width / kBlock) * (height / kBlock), 0.0);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const float* c = &rgb[3 * (y * width + x)];
        blocks[(y / kBlock) * (width / kBlock) + x / kBlock] += 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
      }
    }
    runs.push_back(blocks);
  }
  return runs;
}

void expect_same_expectation(Scene scene, const std::string& scene_file, bool check_bsdf,
                             int film_width = kStrategyWidth, int spp = kStrategySpp) {
  // A small film of the same aspect (the field of view is unchanged), whole blocks only.
  const int width = film_width;
  const int height = std::max(kBlock, (film_width * scene.camera.height / scene.camera.width) / kBlock * kBlock);
  scene.camera.width = width;
  scene.camera.height = height;
  test::SceneOnDevice on_device(scene);
  auto mis = block_means(on_device, width, height, PT_STRATEGY_MIS, spp);
  auto bsdf = check_bsdf ? block_means(on_device, width, height, PT_STRATEGY_BSDF, spp) : mis;
  auto light = block_means(on_device, width, height, PT_STRATEGY_LIGHT, spp);
  const int blocks = static_cast<int>(mis[0].size());
  const double alpha = test::sidak(1e-3, (check_bsdf ? 2 : 1) * blocks);
  for (int b = 0; b < blocks; ++b) {
    std::vector<double> m, f, l;
    for (int k = 0; k < kStrategyRuns; ++k) {
      m.push_back(mis[k][b]);
      f.push_back(bsdf[k][b]);
      l.push_back(light[k][b]);
    }
    if (check_bsdf) {
      EXPECT_GT(test::welch_p(m, f), alpha) << scene_file << " block " << b << ": BSDF sampling differs from MIS";
    }
    EXPECT_GT(test::welch_p(m, l), alpha) << scene_file << " block " << b << ": light sampling differs from MIS";
  }
}

void expect_same_expectation(const std::string& scene_file, bool check_bsdf) {
  expect_same_expectation(load_scene(test::source_scene(scene_file)), scene_file, check_bsdf);
}

TEST(PathTracerStrategies, CornellBoxAgrees) { expect_same_expectation("cornell-box.xml", true); }
TEST(PathTracerStrategies, CausticsBoxAgrees) { expect_same_expectation("cornell-box-caustics.xml", true); }
// BSDF sampling alone finds the plates' smallest lights so rarely that its run means are heavy-
// tailed and a t-test on them is not valid at this budget; light sampling alone is compared.
// Light sampling alone is heavy-tailed in the same way on the two smoothest plates (alpha 0.005
// and 0.02: their lobes are far narrower than the larger lights): it converges to MIS (32768
// spp), but at 64 spp one run of 40 held 15 times the mean, and the t-test rejected at p < 1e-7
// or passed depending on the seeds. Those plates are made as rough as the third (0.07) here.
TEST(PathTracerStrategies, GlossyPlatesLightSamplingAgrees) {
  Scene scene = load_scene(test::source_scene("glossy-plates.xml"));
  for (GdrMaterial& m : scene.materials) {
    if (m.type == BSDF_ROUGH_PLASTIC) m.alpha_u = m.alpha_v = std::max(m.alpha_u, 0.07f);
  }
  expect_same_expectation(scene, "glossy-plates.xml (plates at least 0.07 rough)", false);
}
// Its sun is a directional (delta) light, which only light sampling can reach.
TEST(PathTracerStrategies, EnvironmentLightAgrees) { expect_same_expectation("environment.xml", false); }

TEST(PathTracerStrategies, EnvironmentMapAgrees) {
  Scene scene = test::envmap_scene();
  ASSERT_TRUE(scene.features.light[LIGHT_ENVMAP]);
  // The bright patch makes every estimator noisy: fewer, better-sampled blocks keep the test
  // sensitive (it detects a pdf off by a third).
  expect_same_expectation(scene, "generated envmap scene", true, 16, 32);
}

}  // namespace
}  // namespace gdr
