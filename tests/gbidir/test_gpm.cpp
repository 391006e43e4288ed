// Gradient-domain photon mapping (`gpm`) is consistent. On the diffuse Cornell box (32 x 32,
// max_depth 6), against a long path-traced reference (4096 spp, seed 500;
// support/consistent_gradients.h): the error of its gradients (dx, dy plus the differences of the
// directly seen emission, kept out of them) against the reference's neighbour differences, and
// the error of its primal and of its reconstruction, fall as the passes grow (4, 16, 64: the
// radius shrinks and the estimates add up); its gradients beat the differences of pm's image at
// equal passes (the photon shift correlates the pair); the mean of 8 runs' gradients lies close
// to the reference's differences (no bias the shift adds); its primal agrees with pm's at equal
// passes (the mean brightness of 8 runs each). The same gradient and primal checks on a uniform
// sky over diffuse spheres cover the photons of lights at infinity. The runs are fixed by their
// seeds; the bounds hold with margin over what those runs measure (see the comments), so the
// tests fail on a wrong shift, weight or normalization rather than by chance. The manifold photon
// shift (--shift manifold) on the caustics box: its gradients vary less and its mean and primal
// stay where the refused shift's are. Also: shifts and failed shifts are counted by reason, and
// the parameters are checked.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>

#include "integrators/bidir/bidirectional.h"
#include "integrators/gbidir/gradient_photon_mapping.h"
#include "support/consistent_gradients.h"
#include "support/envmap_scene.h"
#include "support/render.h"
#include "support/test_scenes.h"
#include "util/error.h"

namespace gdr {
namespace {

using test::ConsistencyScene;
using test::consistency_errors;
using test::consistency_settings;
using test::mean;

// Two diffuse spheres on a diffuse plane under a uniform sky (an environment map of one value):
// every photon's first segment comes from a light at infinity. 32 x 24 pixels.
ConsistencyScene& sky_box() {
  static std::unique_ptr<ConsistencyScene> b = std::make_unique<ConsistencyScene>(test::scene_with_environment(
      8, 4, std::vector<float>(32, 1.0f),
      test::spheres_on_plane_xml(R"(<emitter type="envmap"><string name="filename" value="sky.exr"/></emitter>)",
                                 R"(<bsdf type="diffuse"><rgb name="reflectance" value="0.2, 0.6, 0.3"/></bsdf>)")),
      "two spheres on a plane under a uniform sky");
  return *b;
}

// Measured: gradients 0.0234, 0.0087, 0.0031; primal 0.249, 0.022, 0.0052; reconstruction 0.240,
// 0.017, 0.0036 (pm's image: 0.27, 0.029, 0.0079, tests/bidir/test_merging.cpp).
TEST(Gpm, ErrorFallsAsPassesGrow) {
  GradientPhotonMapping gpm(test::consistency_box().on_device.inputs(), gpm_settings({}));
  test::expect_errors_fall_with_passes(gpm, test::consistency_box());
}

// The photon shift is what makes the gradients: at equal passes they are closer to the reference's
// differences than the differences of pm's image are.
void expect_gradients_beat_pm(ConsistencyScene& b, const char* what, double factor) {
  GradientPhotonMapping gpm(b.on_device.inputs(), gpm_settings({}));
  Bidirectional pm(b.on_device.inputs(), pm_settings({}));
  for (int spp : {4, 16}) {
    double e_pm = 0, e_gpm = 0;
    for (uint32_t seed = 1; seed <= 2; ++seed) {
      e_pm += b.image_gradient_relmse(pm.render(consistency_settings(spp, seed)).image.rgb_layer(""));
      e_gpm += consistency_errors(gpm, spp, seed, b).gradients;
    }
    EXPECT_LT(e_gpm, factor * e_pm) << what << " at " << spp << " passes";
  }
}

// Measured: the Cornell box 0.0234 against 0.0847 at 4 passes, 0.0087 against 0.0292 at 16. The
// sky scene 0.648 against 1.099, 0.268 against 0.462; with its sky photons' shifts refused, 1.086
// and 0.456: their shift is what correlates the pairs there.
TEST(Gpm, GradientsBeatPmDifferences) { expect_gradients_beat_pm(test::consistency_box(), "cornell-box", 0.5); }
TEST(Gpm, SkyPhotonsGradientsBeatPmDifferences) { expect_gradients_beat_pm(sky_box(), "sky", 0.75); }

// The gradients converge to the reference's differences, not just to something smooth: the mean of
// 8 runs (seeds 1..8) at 64 passes, whose noise is an eighth of one run's, stays within a bound
// that a shift dropping the photon's change of distance to its parent exceeds (measured: 0.0010;
// without that term 0.0030).
TEST(Gpm, MeanGradientsConverge) {
  GradientPhotonMapping gpm(test::consistency_box().on_device.inputs(), gpm_settings({}));
  EXPECT_LT(test::mean_gradient_relmse(gpm, 64, 8, test::consistency_box()), 0.0018);
}

IntegratorParams params(std::map<std::string, std::string> values) { return IntegratorParams(std::move(values)); }

// Runs seeds 1..runs at `spp` passes: each dx and dy value's sample variance over the runs, and the
// error of the runs' mean gradients against the reference's differences (as mean_gradient_relmse).
struct RunsOfGradients {
  std::vector<double> variance;  // dx then dy
  double mean_error = 0;
  std::vector<double> primal;  // the runs' mean primal
};
RunsOfGradients runs_of_gradients(GradientPathTracer& integrator, int spp, int runs, ConsistencyScene& b) {
  const int w = b.scene.camera.width, h = b.scene.camera.height;
  RunsOfGradients r;
  std::vector<double> sum, sum2;
  for (int seed = 1; seed <= runs; ++seed) {
    GradientImages g = integrator.render_gradients(consistency_settings(spp, uint32_t(seed)));
    r.primal.resize(g.primal.size(), 0.0);
    for (size_t i = 0; i < g.primal.size(); ++i) r.primal[i] += g.primal[i] / double(runs);
    test::add_direct_differences(w, h, g);
    std::vector<float> v = g.dx;
    v.insert(v.end(), g.dy.begin(), g.dy.end());
    sum.resize(v.size(), 0.0);
    sum2.resize(v.size(), 0.0);
    for (size_t i = 0; i < v.size(); ++i) sum[i] += v[i], sum2[i] += double(v[i]) * v[i];
  }
  r.variance.resize(sum.size());
  for (size_t i = 0; i < sum.size(); ++i) r.variance[i] = (sum2[i] - sum[i] * sum[i] / runs) / (runs - 1);
  const size_t half = sum.size() / 2;
  std::vector<float> dx(half), dy(half);
  for (size_t i = 0; i < half; ++i) dx[i] = float(sum[i] / runs), dy[i] = float(sum[half + i] / runs);
  r.mean_error = b.gradient_relmse(dx, dy);
  return r;
}

// The manifold photon shift (--shift manifold) takes the photons behind the spheres' delta
// vertices (light to mirror or glass to the walls and floor), whose shifts the other shifts refuse
// (the base then keeps its full weight): it correlates their pairs. Over 6 runs (seeds 1..6, 8
// passes), many more gradient values vary less than half as much as under the refused shift than
// vary more than twice as much, and the runs' mean gradients are as close to the reference's
// differences. The gradients do not show a flux error of the offsets (a factor on both directions'
// offsets cancels), so the primal is checked too, over the pixels whose gradients vary less: the
// runs' mean against pm's (same seeds and passes, the same photons and camera samples). Measured
// (photon walks of 5 iterations): 2476 of the 6144 values under half the variance, 92 over twice;
// mean error 0.0175 against 0.0178; primal 0.9996 of pm's, and 1.0040 with the offsets' flux 30%
// too high. (The totals of
// the variances hardly differ, 9.8 against 9.9 at 16 passes: a few pixels that see the light in
// the mirror sphere outweigh the rest.)
TEST(Gpm, ManifoldPhotonShiftCorrelatesCaustics) {
  ConsistencyScene& b = test::consistency_scene("cornell-box-caustics.xml");
  const IntegratorParams manifold = params({{"shift", "manifold"}});
  GradientPhotonMapping walked(b.on_device.inputs(), gpm_settings(manifold), manifold);
  GradientPhotonMapping refused(b.on_device.inputs(), gpm_settings({}));
  const RunsOfGradients a = runs_of_gradients(walked, 8, 6, b), c = runs_of_gradients(refused, 8, 6, b);
  size_t lower = 0, higher = 0;
  const size_t pixels = a.variance.size() / 2;
  std::vector<char> walked_pixel(pixels, 0);  // a pixel whose dx or dy varies less than half as much
  for (size_t i = 0; i < a.variance.size(); ++i) {
    const bool less = a.variance[i] < 0.5 * c.variance[i];
    lower += less;
    higher += c.variance[i] < 0.5 * a.variance[i];
    if (less) walked_pixel[(i % pixels) / 3] = 1;
  }
  // Over those pixels, the primal against pm's: the offsets' flux.
  Bidirectional pm(b.on_device.inputs(), pm_settings({}));
  double sum_walked = 0, sum_pm = 0;
  for (size_t i = 0; i < a.primal.size(); ++i) sum_walked += walked_pixel[i / 3] ? a.primal[i] : 0.0;
  for (uint32_t seed = 1; seed <= 6; ++seed) {
    const std::vector<float> image = pm.render(consistency_settings(8, seed)).image.rgb_layer("");
    for (size_t i = 0; i < image.size(); ++i) sum_pm += walked_pixel[i / 3] ? image[i] / 6.0 : 0.0;
  }
  EXPECT_GT(lower, a.variance.size() / 5);
  EXPECT_LT(10 * higher, lower);
  EXPECT_LT(a.mean_error, 1.1 * c.mean_error);
  EXPECT_NEAR(sum_walked / sum_pm, 1.0, 0.002);
}

void expect_primal_agrees_with_pm(ConsistencyScene& b, const char* what) {
  GradientPhotonMapping gpm(b.on_device.inputs(), gpm_settings({}));
  Bidirectional pm(b.on_device.inputs(), pm_settings({}));
  double sum_gpm = 0, sum_pm = 0;
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    sum_gpm += mean(gpm.render_gradients(consistency_settings(16, seed)).primal);
    sum_pm += mean(pm.render(consistency_settings(16, seed)).image.rgb_layer(""));
  }
  EXPECT_NEAR(sum_gpm / sum_pm, 1.0, 0.01) << what;
}

// Measured: 1.00001 on both scenes (the same photons and camera samples; the shifts only move
// weight between neighbours' estimates). A flux error of the sky photons' shift shows here, not in
// the gradients, where a constant factor on both directions' offsets cancels: 30% too much gives
// the sky scene 1.046.
TEST(Gpm, PrimalAgreesWithPm) {
  expect_primal_agrees_with_pm(test::consistency_box(), "cornell-box");
  expect_primal_agrees_with_pm(sky_box(), "sky");
}

// Merges and shifts are counted. The photons of a parent on a delta surface (the caustics box's
// glass sphere) fail their shift, counted as such, and leave the base its full weight, unless the
// manifold photon shift walks them (counted in shifts/manifold; behind the area light, every such
// photon gets its walk); those of lights at infinity (the environment scene's sky and sun, above
// diffuse and rough surfaces only) are all shifted.
void expect_counted(const std::string& file, bool delta_parents, const IntegratorParams& p = {}) {
  Scene scene = test::project_scene(file, 24);
  Stats stats;
  Context ctx(select_device(""), &stats);
  test::SceneOnDevice on_device(scene, &stats, ctx);
  GradientPhotonMapping gpm(on_device.inputs(), gpm_settings(p), p);
  gpm.render_gradients(consistency_settings(2, 7));
  const bool walks = gpm_settings(p).shift == GPT_SHIFT_MANIFOLD;
  EXPECT_GT(stats.count("gpm/merges"), 0u) << file;
  EXPECT_EQ(stats.count("shift_failures/photon_parent") > 0, delta_parents && !walks) << file;
  EXPECT_EQ(stats.count("shifts/manifold") > 0, delta_parents && walks) << file;
  EXPECT_EQ(stats.count("samples/nonfinite_rejected"), 0u) << file;
}

TEST(Gpm, ShiftsAreCounted) {
  expect_counted("cornell-box-caustics.xml", true);
  expect_counted("cornell-box-caustics.xml", true, params({{"shift", "manifold"}}));
  expect_counted("environment.xml", false);
}

TEST(Gpm, ParametersAreChecked) {
  EXPECT_EQ(gpm_settings(params({{"shift", "manifold"}})).shift, GPT_SHIFT_MANIFOLD);
  EXPECT_THROW(gpm_settings(params({{"manifold_iterations", "0"}})), Error);
  EXPECT_EQ(gpm_settings(params({{"shift", "replay"}})).shift, GPT_SHIFT_REPLAY);
  EXPECT_THROW(
      GradientPhotonMapping(test::consistency_box().on_device.inputs(), gpm_settings({}), params({{"radius", "0"}})),
      Error);
}

}  // namespace
}  // namespace gdr
