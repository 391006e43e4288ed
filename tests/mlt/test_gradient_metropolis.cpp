// Gradient-domain Metropolis (`gmlt`) converges: its gradients (plus the differences of the
// directly seen emission, kept out of them) approach the neighbour differences of a long path-
// traced render as the mutations grow (three lengths, two seeds each: the error falls at each
// step, and at 16 times the mutations it is below half the first: a chain's early error falls
// slower than 1 / N, about as 1 / N^0.4 on the caustics box), on the diffuse Cornell
// box (reconnection and half-vector shifts) and on the caustics box (manifold walks through the
// glass sphere); its L2 reconstruction agrees with the path tracer per 4 x 4 block over 16
// independent renders of each (gmlt seeds 1..16, pt 101..116; Welch, family false-positive rate
// 1e-3, support/agreement.h). Failed shifts are counted; the weighted reconstruction is refused.
#include <gtest/gtest.h>

#include "integrators/mlt/gradient_metropolis.h"
#include "support/agreement.h"
#include "support/render.h"
#include "support/test_scenes.h"
#include "util/error.h"

namespace gdr {
namespace {

constexpr int kRuns = 16;

// 2048 chains: a step is about 3.5 mutations a pixel at 24 x 24.
IntegratorParams small_gmlt(std::map<std::string, std::string> extra = {}) {
  extra.emplace("chains", "2048");  // unless `extra` names another count
  extra.emplace("bootstrap", "32768");
  return IntegratorParams(extra);
}

// Mean squared error of (dx + the direct layer's dx, dy + ...) against the reference's neighbour
// differences, over the pairs inside the image.
double gradient_error(const GradientImages& g, const std::vector<float>& reference) {
  const int w = g.width, h = g.height;
  double sum = 0;
  size_t n = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        size_t i = 3 * (size_t(y) * w + x) + c;
        if (x + 1 < w) {
          double d = g.dx[i] + (g.direct[i + 3] - g.direct[i]) - (reference[i + 3] - reference[i]);
          sum += d * d;
          ++n;
        }
        if (y + 1 < h) {
          size_t j = i + 3 * size_t(w);
          double d = g.dy[i] + (g.direct[j] - g.direct[i]) - (reference[j] - reference[i]);
          sum += d * d;
          ++n;
        }
      }
    }
  }
  return sum / double(n);
}

// Three renders of 1, 4 and 16 times `passes` passes.
void expect_gradients_converge(const Scene& scene, const std::string& name, int reference_spp, int chains,
                               int passes) {
  test::SceneOnDevice on_device(scene);
  RenderSettings s;
  s.max_depth = 6;
  s.spp = reference_spp;
  s.seed = 1000;
  std::vector<float> reference = PathTracer(on_device.inputs(), PtSettings{}).render(s).image.rgb_layer("");
  IntegratorParams params = small_gmlt({{"chains", std::to_string(chains)}});
  GradientMetropolis gmlt(on_device.inputs(), gmlt_settings(params), params);
  std::vector<double> error;
  for (int n : {passes, 4 * passes, 16 * passes}) {
    double e = 0;
    for (uint32_t seed : {1u, 2u}) {
      s.spp = n;
      s.seed = seed;
      e += 0.5 * gradient_error(gmlt.render_gradients(s), reference);
    }
    error.push_back(e);
  }
  EXPECT_LT(error[1], error[0]) << name;
  EXPECT_LT(error[2], error[1]) << name;
  EXPECT_LT(error[2], 0.5 * error[0]) << name << ": errors " << error[0] << ", " << error[1] << ", " << error[2];
}

TEST(Gmlt, CornellBoxGradientsConvergeToPtDifferences) {
  expect_gradients_converge(test::project_scene("cornell-box.xml", 24), "cornell-box.xml", 4096, 2048, 4);
}

TEST(Gmlt, CausticsBoxGradientsConvergeThroughManifoldWalks) {
  expect_gradients_converge(test::project_scene("cornell-box-caustics.xml", 24), "cornell-box-caustics.xml", 4096, 2048,
                            2);
}

TEST(Gmlt, L2ReconstructionAgreesWithPt) {
  Scene scene = test::project_scene("cornell-box.xml", 24);
  test::SceneOnDevice on_device(scene);
  IntegratorParams params = small_gmlt({{"recon", "l2"}});
  GradientMetropolis gmlt(on_device.inputs(), gmlt_settings(params), params);
  PathTracer pt(on_device.inputs(), PtSettings{});
  const int w = scene.camera.width, h = scene.camera.height;
  test::expect_blocks_agree(test::block_means(gmlt, w, h, 16, 6, 1, kRuns), test::block_means(pt, w, h, 8, 6, 101, kRuns),
                            "cornell-box.xml (L2)", "gmlt", "pt");
}

// Offsets past the image's edge fail and are counted; the chains' steps are counted by kind.
TEST(Gmlt, StatsCountFailedShiftsAndSteps) {
  Scene scene = test::project_scene("cornell-box.xml", 16);
  Stats stats;
  Context context(select_device(""), &stats);
  test::SceneOnDevice on_device(scene, &stats, context);
  IntegratorParams params = small_gmlt();
  GradientMetropolis gmlt(on_device.inputs(), gmlt_settings(params), params);
  RenderSettings s;
  s.spp = 4;
  RenderResult r = gmlt.render(s);
  EXPECT_GT(stats.count("shift_failures/outside_image"), 0u);
  EXPECT_EQ(stats.count("mlt/small_steps") + stats.count("mlt/large_steps"), uint64_t(2048) * r.samples);
  EXPECT_EQ(stats.count("samples/nonfinite_rejected"), 0u);
  EXPECT_TRUE(r.image.has_rgb_layer("dx") && r.image.has_rgb_layer("dy") && r.image.has_rgb_layer("primal"));
  EXPECT_GT(gmlt.normalization(), 0.0);
}

TEST(Gmlt, ParametersAreChecked) {
  using Values = std::map<std::string, std::string>;
  for (const Values& bad : {Values{{"recon", "weighted"}}, Values{{"target_alpha", "0"}}, Values{{"shift", "bent"}}}) {
    EXPECT_THROW(gmlt_settings(IntegratorParams(bad)), Error) << bad.begin()->first;
  }
  GmltSettings s = gmlt_settings(IntegratorParams(Values{{"target_alpha", "0.5"}}));
  EXPECT_FLOAT_EQ(s.target_alpha, 0.5f);
  EXPECT_EQ(s.gpt.shift, GPT_SHIFT_MANIFOLD);
}

}  // namespace
}  // namespace gdr
