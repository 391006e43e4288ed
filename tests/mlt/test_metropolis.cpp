// Metropolis light transport (`mlt`) converges to the path tracer's image on a diffuse and a
// glossy scene: per 4 x 4 block (and whole image) Welch t-tests over 16 independent renders of
// each (mlt seeds 1..16, its chains independent across seeds; pt seeds 101..116), at a family
// false-positive rate of 1e-3 (support/agreement.h). Its normalization b (the target's integral
// over primary sample space) is the image's luminance summed over the pixels, tested against
// pt's sums over the same 16 + 16 renders (Welch, false-positive rate 1e-3). Same seed, same
// image; parameters checked; the stats count the chains' steps by kind; start_cap spreads the
// chains a lone bright bootstrap sample would start.
#include <gtest/gtest.h>

#include "integrators/mlt/metropolis.h"
#include "support/agreement.h"
#include "support/render.h"
#include "support/test_scenes.h"
#include "util/error.h"

namespace gdr {
namespace {

constexpr int kMltRuns = 16;

// A short render's settings for a film of a few hundred pixels: 2048 chains (one step of all of
// them is about 3.5 mutations a pixel at 24 x 24), a bootstrap of 2^16 samples.
MltIntegratorSettings small_mlt() {
  return mlt_settings(IntegratorParams({{"chains", "2048"}, {"bootstrap", "65536"}}));
}

double luminance_sum(const std::vector<float>& rgb) {
  double sum = 0;
  for (size_t i = 0; i + 2 < rgb.size(); i += 3) sum += 0.212671 * rgb[i] + 0.715160 * rgb[i + 1] + 0.072169 * rgb[i + 2];
  return sum;
}

void expect_agrees_with_pt(const Scene& scene, const std::string& name, int passes, int max_depth) {
  test::SceneOnDevice on_device(scene);
  Metropolis mlt(on_device.inputs(), small_mlt());
  PathTracer pt(on_device.inputs(), PtSettings{});
  const int w = scene.camera.width, h = scene.camera.height;
  test::expect_blocks_agree(test::block_means(mlt, w, h, passes, max_depth, 1, kMltRuns),
                            test::block_means(pt, w, h, 8, max_depth, 101, kMltRuns), name, "mlt", "pt");
}

TEST(Mlt, CornellBoxAgreesWithPt) {
  expect_agrees_with_pt(test::project_scene("cornell-box.xml", 24), "cornell-box.xml", 32, 6);
}

// The plates at least 0.2 rough, as for bdpt (tests/bidir/test_bdpt.cpp): pt's light-sampled
// runs on the smoother ones are too heavy-tailed for a t-test over 16 runs.
TEST(Mlt, GlossyPlatesAgreeWithPt) {
  Scene scene = test::project_scene("glossy-plates.xml", 32);
  for (GdrMaterial& m : scene.materials) {
    if (m.type == BSDF_ROUGH_PLASTIC) m.alpha_u = m.alpha_v = std::max(m.alpha_u, 0.2f);
  }
  expect_agrees_with_pt(scene, "glossy-plates.xml (plates at least 0.2 rough)", 32, 6);
}

TEST(Mlt, NormalizationIsTheImagesLuminanceSum) {
  Scene scene = test::project_scene("cornell-box.xml", 24);
  test::SceneOnDevice on_device(scene);
  Metropolis mlt(on_device.inputs(), small_mlt());
  PathTracer pt(on_device.inputs(), PtSettings{});
  std::vector<double> b, sums;
  for (int k = 0; k < kMltRuns; ++k) {
    RenderSettings s;
    s.spp = 4;
    s.max_depth = 6;
    s.seed = 1 + k;
    mlt.render(s);
    b.push_back(mlt.normalization());
    s.seed = 101 + k;
    s.spp = 8;
    sums.push_back(luminance_sum(pt.render(s).image.rgb_layer("")));
  }
  EXPECT_GT(test::welch_p(b, sums), 1e-3) << "b " << test::mean_and_variance(b).mean << ", pt's sum "
                                          << test::mean_and_variance(sums).mean;
}

TEST(Mlt, SameSeedSameImage) {
  Scene scene = test::project_scene("cornell-box.xml", 16);
  test::SceneOnDevice on_device(scene);
  Metropolis mlt(on_device.inputs(), small_mlt());
  RenderSettings s;
  s.spp = 4;
  s.seed = 3;
  std::vector<float> a = mlt.render(s).image.rgb_layer(""), b = mlt.render(s).image.rgb_layer("");
  EXPECT_EQ(a, b);
  s.seed = 4;
  EXPECT_NE(a, mlt.render(s).image.rgb_layer(""));
}

// Every step of every chain is a small or a large step, counted; the bootstrap's samples and the
// chains are reported; nothing non-finite reached the film.
TEST(Mlt, StatsCountTheSteps) {
  Scene scene = test::project_scene("cornell-box.xml", 16);
  Stats stats;
  Context context(select_device(""), &stats);
  test::SceneOnDevice on_device(scene, &stats, context);
  Metropolis mlt(on_device.inputs(), small_mlt());
  RenderSettings s;
  s.spp = 8;
  RenderResult r = mlt.render(s);
  const uint64_t steps = stats.count("mlt/small_steps") + stats.count("mlt/large_steps");
  EXPECT_EQ(steps, uint64_t(2048) * r.samples);  // 16 x 16 pixels: one step a pass
  EXPECT_GT(stats.count("mlt/small_steps_accepted"), 0u);
  EXPECT_GT(stats.count("mlt/large_steps_accepted"), 0u);
  EXPECT_LT(stats.count("mlt/small_steps_accepted"), stats.count("mlt/small_steps"));
  EXPECT_EQ(stats.count("mlt/bootstrap_samples"), 65536u);
  EXPECT_EQ(stats.count("samples/nonfinite_rejected"), 0u);
  nlohmann::json j = stats.to_json();
  EXPECT_EQ(j["mlt"]["chains"], 2048);
  EXPECT_GT(j["mlt"]["normalization"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["mlt"]["acceptance"]["small_steps"].get<double>(),
                   double(stats.count("mlt/small_steps_accepted")) / double(stats.count("mlt/small_steps")));
  EXPECT_DOUBLE_EQ(j["mlt"]["acceptance"]["large_steps"].get<double>(),
                   double(stats.count("mlt/large_steps_accepted")) / double(stats.count("mlt/large_steps")));
}

// On the glass box (light seen and lit through glass), a bootstrap of 16384 samples holds lone
// bright paths that, drawn in proportion to f, start dozens of the 1024 chains each (68 and 55 at
// seeds 2 and 3, against 14 to 37 at seeds 1, 4, 5, 6; fixed seeds, so the check is
// deterministic); with start_cap 16 none starts more than a quarter of that (9 at both).
TEST(Mlt, StartCapSpreadsTheChainsOfALoneBrightSample) {
  Scene scene = test::project_scene("glass-box.xml", 32);
  for (uint32_t seed : {2u, 3u}) {
    size_t most[2];
    for (int capped = 0; capped < 2; ++capped) {
      Stats stats;
      Context context(select_device(""), &stats);
      test::SceneOnDevice on_device(scene, &stats, context);
      std::map<std::string, std::string> p = {{"chains", "1024"}, {"bootstrap", "16384"}};
      if (capped) p["start_cap"] = "16";
      Metropolis mlt(on_device.inputs(), mlt_settings(IntegratorParams(p)));
      RenderSettings s;
      s.spp = 1;
      s.seed = seed;
      s.max_depth = scene.max_depth;
      mlt.render(s);
      most[capped] = stats.to_json()["mlt"]["start_duplicates"].get<size_t>();
    }
    EXPECT_GT(most[0], 40u) << "seed " << seed << ": the case has no lone bright sample";
    EXPECT_LT(4 * most[1], most[0]) << "seed " << seed;
  }
}

TEST(Mlt, ParametersAreChecked) {
  for (auto bad : std::vector<std::map<std::string, std::string>>{
           {{"sigma", "0"}}, {{"sigma", "2"}}, {{"large_step", "1.5"}}, {{"chains", "0"}}, {{"chains", "1.5"}},
           {{"bootstrap", "0"}}, {{"mutations_per_pixel", "0"}}, {{"mis", "cubic"}}, {{"start_cap", "1.5"}}}) {
    EXPECT_THROW(mlt_settings(IntegratorParams(bad)), Error) << bad.begin()->first << "=" << bad.begin()->second;
  }
  MltIntegratorSettings s = mlt_settings(IntegratorParams({{"sigma", "0.05"}, {"large_step", "0"}, {"chains", "64"}}));
  EXPECT_FLOAT_EQ(s.loop.mutation.sigma, 0.05f);
  EXPECT_EQ(s.loop.mutation.large_step, 0.0f);
  EXPECT_EQ(s.loop.chains, 64u);
}

}  // namespace
}  // namespace gdr
