// The weighted reconstruction of G-PT renders keeps the image's brightness: each half of the
// passes is weighted by the other half's variance estimates, so no weight depends on the values
// it weights and the solve stays unbiased. (Weights from a render's own estimates fail this: a
// rare bright path raises a pixel's variance estimate with its value, loses weight and the image
// comes out darker, by a few percent on the caustics scene.)
//
// kReconRuns renders (seeds 1.., kReconSpp passes each); per render, d = mean over the image of
// (reconstruction - primal), whose expectation is 0 for an unbiased reconstruction. A t-test of
// mean(d) = 0 over the runs (paired: the primal's own noise cancels in d), per scene at a
// false-positive rate of 1e-3.
#include <gtest/gtest.h>

#include "integrators/gpt/gradient_path_tracer.h"
#include "scene/load_scene.h"
#include "support/render.h"
#include "support/source_scene.h"
#include "support/statistics.h"

namespace gdr {
namespace {

constexpr int kReconWidth = 24, kReconSpp = 8, kReconRuns = 16, kReconMaxDepth = 8;

void expect_brightness_kept(const std::string& scene_file) {
  Scene scene = load_scene(test::source_scene(scene_file));
  scene.camera.width = kReconWidth;
  scene.camera.height = std::max(2, kReconWidth * scene.camera.height / scene.camera.width);
  test::SceneOnDevice on_device(scene);
  GradientPathTracer gpt(on_device.inputs(), GptSettings{});
  const ReconSettings weighted = recon_settings("weighted", 1.0f, "fast");
  std::vector<double> d, brightness;
  for (int k = 0; k < kReconRuns; ++k) {
    RenderSettings s;
    s.spp = kReconSpp;
    s.seed = uint32_t(1 + k);
    s.max_depth = kReconMaxDepth;
    GradientImages g = gpt.render_gradients(s);
    ASSERT_FALSE(g.halves[0].primal.empty());
    ASSERT_FALSE(g.halves[1].primal.empty());
    Image image = gradient_image(test::default_context(), g, weighted, nullptr);
    // The halves' layers are saved with the weighted form, so --reconstruct can weight them again.
    ASSERT_TRUE(image.has_rgb_layer("even.primal_variance") && image.has_rgb_layer("odd.dy"));
    std::vector<float> rgb = image.rgb_layer("");
    double diff = 0, primal = 0;
    for (size_t i = 0; i < rgb.size(); ++i) {
      ASSERT_TRUE(std::isfinite(rgb[i]));
      diff += double(rgb[i]) - g.primal[i];
      primal += g.primal[i];
    }
    d.push_back(diff / double(rgb.size()));
    brightness.push_back(primal / double(rgb.size()));
  }
  test::MeanVar mv = test::mean_and_variance(d), mb = test::mean_and_variance(brightness);
  ASSERT_GT(mv.var_of_mean, 0.0);
  const double t = mv.mean / std::sqrt(mv.var_of_mean);
  EXPECT_GT(test::student_t_two_sided_p(t, kReconRuns - 1), 1e-3)
      << scene_file << ": weighted reconstruction minus primal " << mv.mean << " +- " << std::sqrt(mv.var_of_mean)
      << " (image mean " << mb.mean << ")";
}

TEST(GptWeightedRecon, KeepsBrightnessCornellBox) { expect_brightness_kept("cornell-box.xml"); }
TEST(GptWeightedRecon, KeepsBrightnessCaustics) { expect_brightness_kept("cornell-box-caustics.xml"); }

}  // namespace
}  // namespace gdr
