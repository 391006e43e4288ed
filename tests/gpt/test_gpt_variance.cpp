// G-PT's per-pixel variance estimates (of the means primal, dx and dy) are unbiased: over many
// seeds, their mean must match the empirical variance of the pixel means across those seeds.
//
// kGroups groups of kPerGroup renders (seeds 1.., kVarianceSpp passes each). In group g and image block
// b (a quadrant, summed over its pixels and channels), T = mean over the group's renders of the
// summed estimates - the summed sample variances (over the group's renders) of the pixel means.
// Both terms estimate the same sum of variances without bias, so T has mean 0, and the groups
// are independent: a z-test of mean(T) = 0 with the standard error taken from the spread of T
// over the groups (so Student's t with kGroups - 1 degrees of freedom, which heavy-tailed pixel
// distributions do not invalidate the way a per-pixel z-test would). 3 layers x 4 blocks,
// Šidák-corrected to a false-positive rate of 1e-3 for the whole test. An estimator off by the
// factor (n-1)/n or n (variance of one pass instead of the mean) fails it.
#include <gtest/gtest.h>

#include "integrators/gpt/gradient_path_tracer.h"
#include "scene/load_scene.h"
#include "support/render.h"
#include "support/source_scene.h"
#include "support/statistics.h"

namespace gdr {
namespace {

constexpr int kVarianceWidth = 16, kVarianceSpp = 4, kGroups = 12, kPerGroup = 8, kVarianceMaxDepth = 8;

struct Layer {
  const char* name;
  std::vector<float> GradientImages::*mean;
  std::vector<float> GradientImages::*variance;
};
const Layer kLayers[] = {{"primal", &GradientImages::primal, &GradientImages::primal_variance},
                         {"dx", &GradientImages::dx, &GradientImages::dx_variance},
                         {"dy", &GradientImages::dy, &GradientImages::dy_variance}};

void expect_unbiased_variance(const std::string& scene_file) {
  Scene scene = load_scene(test::source_scene(scene_file));
  const int w = kVarianceWidth, h = std::max(2, (kVarianceWidth * scene.camera.height / scene.camera.width) / 2 * 2);
  scene.camera.width = w;
  scene.camera.height = h;
  test::SceneOnDevice on_device(scene);
  GradientPathTracer gpt(on_device.inputs(), GptSettings{});
  auto block = [&](size_t value) {  // quadrant of an interleaved RGB value
    size_t p = value / 3;
    return int((p % w) >= size_t(w / 2)) + 2 * int((p / w) >= size_t(h / 2));
  };
  // t[layer][block]: T of each group.
  std::vector<std::vector<std::vector<double>>> t(3, std::vector<std::vector<double>>(4));
  double estimated_total = 0;
  int seed = 1;
  for (int group = 0; group < kGroups; ++group) {
    std::vector<GradientImages> runs;
    for (int k = 0; k < kPerGroup; ++k) {
      RenderSettings s;
      s.spp = kVarianceSpp;
      s.seed = uint32_t(seed++);
      s.max_depth = kVarianceMaxDepth;
      runs.push_back(gpt.render_gradients(s));
      ASSERT_EQ(runs.back().samples, kVarianceSpp);
    }
    for (int l = 0; l < 3; ++l) {
      const Layer& layer = kLayers[l];
      double estimate[4] = {0, 0, 0, 0}, empirical[4] = {0, 0, 0, 0};
      const size_t n = (runs[0].*layer.mean).size();
      for (size_t i = 0; i < n; ++i) {
        double sum = 0, sum_sq = 0, est = 0;
        for (const GradientImages& r : runs) {
          const double m = (r.*layer.mean)[i], v = (r.*layer.variance)[i];
          ASSERT_TRUE(std::isfinite(v) && v >= 0) << layer.name << " variance " << v;
          sum += m;
          sum_sq += m * m;
          est += v;
        }
        const double mean = sum / kPerGroup;
        estimate[block(i)] += est / kPerGroup;
        empirical[block(i)] += std::max(0.0, sum_sq - kPerGroup * mean * mean) / (kPerGroup - 1);
      }
      for (int b = 0; b < 4; ++b) {
        t[l][b].push_back(estimate[b] - empirical[b]);
        estimated_total += estimate[b];
      }
    }
  }
  EXPECT_GT(estimated_total, 0.0) << "no variance estimated at all";
  const double alpha = test::sidak(1e-3, 3 * 4);
  for (int l = 0; l < 3; ++l) {
    for (int b = 0; b < 4; ++b) {
      test::MeanVar mv = test::mean_and_variance(t[l][b]);
      const double z = mv.var_of_mean > 0 ? mv.mean / std::sqrt(mv.var_of_mean) : (mv.mean == 0 ? 0.0 : INFINITY);
      EXPECT_GT(test::student_t_two_sided_p(z, kGroups - 1), alpha)
          << scene_file << ": " << kLayers[l].name << " block " << b << ": estimates minus empirical variance "
          << mv.mean << " +- " << std::sqrt(mv.var_of_mean);
    }
  }
}

TEST(GptVariance, EstimatesAreUnbiasedCornellBox) { expect_unbiased_variance("cornell-box.xml"); }
TEST(GptVariance, EstimatesAreUnbiasedGlossyPlates) { expect_unbiased_variance("glossy-plates.xml"); }

// One pass has no spread to estimate: the estimates are 0, never NaN.
TEST(GptVariance, OnePassGivesZeroEstimates) {
  Scene scene = load_scene(test::source_scene("cornell-box.xml"));
  scene.camera.width = 8;
  scene.camera.height = 8;
  test::SceneOnDevice on_device(scene);
  GradientPathTracer gpt(on_device.inputs(), GptSettings{});
  RenderSettings s;
  s.spp = 1;
  GradientImages g = gpt.render_gradients(s);
  for (const Layer& layer : kLayers) {
    const std::vector<float>& v = g.*layer.variance;
    ASSERT_EQ(v.size(), (g.*layer.mean).size()) << layer.name;
    for (float x : v) ASSERT_EQ(x, 0.0f) << layer.name;
  }
}

}  // namespace
}  // namespace gdr
