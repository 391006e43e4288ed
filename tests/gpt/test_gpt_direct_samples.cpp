// The direct layer's extra camera samples (--direct-samples, integrators/gpt/direct_samples.h:
// every pixel in the first pass, then those near an emitter's edge) leave the direct layer and the
// primal unbiased and cut the direct layer's variance by about 1 + K.
//
// The caustics box (its light seen from the camera), kWidth px, kSpp passes: kSeeds renders with
// K = 0 (seeds 1..) and kSeeds with K = kExtra (seeds 1001..). Unbiased: Welch's t-test of equal
// means of each render's summed direct layer, and of its summed primal, at a false-positive rate of
// 1e-3 for the whole test (Šidák over 2 integrators x 2 layers). Variance: the summed per-pixel
// variances of the direct layer over the seeds, K = kExtra over K = 0, expected 1 / (1 + kExtra)
// = 0.25, must be below 0.5: over eight sets of seeds (gpt; about 30 pixels on the light's edge)
// it lay between 0.19 and 0.28, a spread of about 0.03, which puts 0.5 some eight spreads above.
#include <gtest/gtest.h>

#include "integrators/gbidir/gradient_bidirectional.h"
#include "integrators/gpt/gradient_path_tracer.h"
#include "scene/load_scene.h"
#include "support/render.h"
#include "support/statistics.h"
#include "support/agreement.h"

namespace gdr {
namespace {

constexpr int kWidth = 32, kSpp = 4, kSeeds = 24, kExtra = 3, kMaxDepth = 6;

struct Sums {
  std::vector<double> direct, primal;      // each render's summed layer
  std::vector<std::vector<float>> images;  // each render's direct layer
};

double sum(const std::vector<float>& v) {
  double s = 0;
  for (float x : v) s += x;
  return s;
}

// The summed per-pixel sample variances of the images over the renders.
double summed_variance(const std::vector<std::vector<float>>& images) {
  double total = 0;
  const double n = double(images.size());
  for (size_t i = 0; i < images[0].size(); ++i) {
    double s = 0, s2 = 0;
    for (const std::vector<float>& im : images) {
      s += im[i];
      s2 += double(im[i]) * im[i];
    }
    total += std::max(0.0, s2 - s * s / n) / (n - 1);
  }
  return total;
}

template <class Make>
Sums render_seeds(const Scene& scene, int extra, uint32_t first_seed, Make make) {
  test::SceneOnDevice on_device(scene);
  IntegratorParams params;
  params.set("direct_samples", std::to_string(extra));
  auto integrator = make(on_device.inputs(), params);
  Sums out;
  for (int i = 0; i < kSeeds; ++i) {
    RenderSettings s;
    s.spp = kSpp;
    s.seed = first_seed + uint32_t(i);
    s.max_depth = kMaxDepth;
    GradientImages g = integrator->render_gradients(s);
    out.direct.push_back(sum(g.direct));
    out.primal.push_back(sum(g.primal));
    out.images.push_back(std::move(g.direct));
  }
  return out;
}

template <class Make>
void expect_unbiased_and_less_noisy(const char* name, Make make) {
  Scene scene = load_scene(test::source_scene("cornell-box-caustics.xml"));
  scene.camera.height = kWidth * scene.camera.height / scene.camera.width;
  scene.camera.width = kWidth;
  const Sums plain = render_seeds(scene, 0, 1, make), extra = render_seeds(scene, kExtra, 1001, make);
  const double alpha = test::sidak(1e-3, 4);
  EXPECT_GT(test::welch_p(plain.direct, extra.direct), alpha)
      << name << ": summed direct layer " << test::mean_and_variance(plain.direct).mean << " (K = 0) vs "
      << test::mean_and_variance(extra.direct).mean << " (K = " << kExtra << ")";
  EXPECT_GT(test::welch_p(plain.primal, extra.primal), alpha)
      << name << ": summed primal " << test::mean_and_variance(plain.primal).mean << " (K = 0) vs "
      << test::mean_and_variance(extra.primal).mean << " (K = " << kExtra << ")";
  const double v0 = summed_variance(plain.images), v = summed_variance(extra.images);
  ASSERT_GT(v0, 0.0) << name << ": the direct layer has no variance: is the light seen?";
  EXPECT_LT(v / v0, 0.5) << name << ": direct layer's variance with K = " << kExtra << " over K = 0";
}

TEST(GptDirectSamples, GptDirectLayerUnbiasedAndLessNoisy) {
  expect_unbiased_and_less_noisy("gpt", [](const RenderInputs& in, const IntegratorParams& p) {
    return std::make_unique<GradientPathTracer>(in, gpt_settings(p), p);
  });
}

// G-VCM's direct layer also holds the light-traced paths it cannot shift: only the seen emission
// is averaged over the extra samples.
TEST(GptDirectSamples, GvcmDirectLayerUnbiasedAndLessNoisy) {
  expect_unbiased_and_less_noisy("gvcm", [](const RenderInputs& in, const IntegratorParams& p) {
    return std::make_unique<GradientBidirectional>(in, gvcm_settings(p), p, gvcm_photon_settings(p));
  });
}

// After the first pass only the pixels near the light's edge take extra samples: the passes after
// it list a small share of the image (the light covers about 1% of the caustics box's image).
TEST(GptDirectSamples, AfterTheFirstPassOnlyNearEdges) {
  Scene scene = test::project_scene("cornell-box-caustics.xml", 64);
  Stats stats;
  test::SceneOnCountingDevice on_device(scene, &stats);
  IntegratorParams params;
  params.set("direct_samples", "2");
  RenderSettings s;
  s.spp = 5;
  s.seed = 3;
  s.max_depth = kMaxDepth;
  GradientPathTracer(on_device.inputs(), gpt_settings(params), params).render_gradients(s);
  const uint64_t pixels = uint64_t(scene.camera.width) * scene.camera.height;
  const uint64_t rays = stats.count("kernel_items/seen_camera_listed");
  ASSERT_GE(rays, 2 * pixels) << "the first pass takes extra samples everywhere";
  const double later = double(rays - 2 * pixels) / (2.0 * (s.spp - 1));  // pixels a later pass
  EXPECT_GT(later, 0.0) << "no pixel near the light's edge took extra samples";
  EXPECT_LT(later, 0.1 * double(pixels)) << "extra samples beyond the light's edges";
}

TEST(GptDirectSamples, ParameterIsChecked) {
  IntegratorParams p;
  p.set("direct_samples", "-1");
  EXPECT_THROW(gpt_settings(p), Error);
  p.set("direct_samples", "5");
  EXPECT_EQ(gpt_settings(p).direct_samples, 5);
}

// max_depth 0 renders nothing (tests/pt/test_max_depth.cpp), the direct samples' emission too.
TEST(GptDirectSamples, MaxDepthZeroStaysBlack) {
  LoadOptions o;
  o.defines = {{"res", "16"}};
  Scene scene = load_scene(test::source_scene("cornell-box.xml"), o);
  test::SceneOnDevice on_device(scene);
  IntegratorParams params;
  params.set("direct_samples", "8");
  params.set("recon", "none");
  GradientPathTracer gpt(on_device.inputs(), gpt_settings(params), params);
  RenderSettings s;
  s.spp = 2;
  s.max_depth = 0;
  double sum = 0;
  for (float v : gpt.render(s).image.rgb_layer("")) sum += v;
  EXPECT_EQ(sum, 0.0);
}

}  // namespace
}  // namespace gdr
