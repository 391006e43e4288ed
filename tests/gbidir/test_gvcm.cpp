// Gradient-domain vertex connection and merging (`gvcm`) is consistent. On the diffuse Cornell box
// (32 x 32, max_depth 6), against a long path-traced reference (4096 spp, seed 500;
// support/consistent_gradients.h): the error of its gradients against the reference's neighbour
// differences, of its primal and of its reconstruction fall as the passes grow (4, 16, 64: the
// radius shrinks and the estimates add up); at equal passes its gradients beat the differences of
// vcm's image (the shifts correlate the pairs);
// the mean of 8 runs' gradients lies close to the reference's differences; its primal agrees with
// vcm's (balance heuristic) at equal passes, on the Cornell box and on the caustics box (mirror and
// glass sphere: specular-diffuse-specular paths). The runs are fixed by their seeds; the bounds
// hold with margin over what those runs measure (see the comments), so the tests fail on a wrong
// shift, weight or normalization rather than by chance. Also: merges, connections and failed
// photon shifts are counted, and the parameters are checked.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>

#include "integrators/bidir/bidirectional.h"
#include "integrators/gbidir/gradient_bidirectional.h"
#include "support/consistent_gradients.h"
#include "support/render.h"
#include "util/error.h"

namespace gdr {
namespace {

using test::ConsistencyScene;
using test::consistency_errors;
using test::consistency_settings;

std::unique_ptr<GradientBidirectional> gvcm(const RenderInputs& in, const IntegratorParams& p = {}) {
  return std::make_unique<GradientBidirectional>(in, gvcm_settings(p), p, gvcm_photon_settings(p));
}

Bidirectional vcm_balance(const RenderInputs& in) {
  BidirSettings s = vcm_settings({});
  s.options.mis = BIDIR_MIS_BALANCE;
  return Bidirectional(in, s);
}

// Measured (means of the two runs): gradients 0.0070, 0.0020, 0.00061 (0.0129, 0.0037, 0.0011
// with light tracing left unshifted); primal 0.231, 0.0157, 0.0029; reconstruction 0.228, 0.0145,
// 0.0026.
TEST(Gvcm, ErrorFallsAsPassesGrow) {
  auto g = gvcm(test::consistency_box().on_device.inputs());
  test::expect_errors_fall_with_passes(*g, test::consistency_box());
}

// Measured at 4 and 16 passes (sums of the two seeds): gvcm 0.0140 and 0.0041, vcm's differences
// 0.0655 and 0.0164 (ratios 0.21, 0.25); with light tracing left unshifted gvcm 0.0258 and 0.0075
// (0.39, 0.46).
TEST(Gvcm, GradientsBeatVcmDifferences) {
  ConsistencyScene& b = test::consistency_box();
  auto g = gvcm(b.on_device.inputs());
  Bidirectional vcm = vcm_balance(b.on_device.inputs());
  for (int spp : {4, 16}) {
    double e_gvcm = 0, e_vcm = 0;
    for (uint32_t seed = 1; seed <= 2; ++seed) {
      e_gvcm += consistency_errors(*g, spp, seed, b).gradients;
      e_vcm += b.image_gradient_relmse(vcm.render(consistency_settings(spp, seed)).image.rgb_layer(""));
    }
    EXPECT_LT(e_gvcm, 0.35 * e_vcm) << spp << " passes";
  }
}

// The gradients converge to the reference's differences, not just to something smooth: the mean of
// 8 runs (seeds 1..8) at 64 passes, whose noise is an eighth of one run's (measured 0.00027;
// before light tracing was shifted 0.00033, and with the merges' light-side share halved in their
// weights then 0.00049).
TEST(Gvcm, MeanGradientsConverge) {
  auto g = gvcm(test::consistency_box().on_device.inputs());
  EXPECT_LT(test::mean_gradient_relmse(*g, 64, 8, test::consistency_box()), 0.00045);
}

void expect_primal_agrees_with_vcm(const std::string& file, double tolerance, const IntegratorParams& params = {}) {
  ConsistencyScene& b = test::consistency_scene(file);
  auto g = gvcm(b.on_device.inputs(), params);
  Bidirectional vcm = vcm_balance(b.on_device.inputs());
  double sum_gvcm = 0, sum_vcm = 0;
  for (uint32_t seed = 1; seed <= 8; ++seed) {
    sum_gvcm += test::mean(g->render_gradients(consistency_settings(16, seed)).primal);
    sum_vcm += test::mean(vcm.render(consistency_settings(16, seed)).image.rgb_layer(""));
  }
  EXPECT_NEAR(sum_gvcm / sum_vcm, 1.0, tolerance) << file;
}

// Measured (8 runs of 16 passes each, seeds 1..8): 1.0006 on the Cornell box, 0.9997 on the
// caustics box; with the merges' light-side share halved in their weights 1.038 and 1.039.
TEST(Gvcm, PrimalAgreesWithVcm) {
  expect_primal_agrees_with_vcm("cornell-box.xml", 0.01);
  expect_primal_agrees_with_vcm("cornell-box-caustics.xml", 0.01);
}

// With the manifold shift (the offsets' sums through the walks' vertices), on the caustics box:
// measured 0.9996 (0.9976 with the sums left as they were before the walk: a bias this bound does
// not resolve).
TEST(Gvcm, PrimalAgreesWithVcmUnderManifoldShift) {
  expect_primal_agrees_with_vcm("cornell-box-caustics.xml", 0.01,
                                IntegratorParams(std::map<std::string, std::string>{{"shift", "manifold"}}));
}

// Merges and connections are counted; the caustics box's photons from the glass sphere (a delta
// parent) fail their shift, counted, and leave the base the pair's weight, unless the manifold
// photon shift walks them (each solved walk's reverse ray counted in rays/photon_reverse); light
// tracing's vertices behind a delta vertex likewise stay unshifted, counted as photon_parent
// failures too, unless walked. Measured (24 px, 2 passes, seed 7): the caustics box's
// photon_parent failures fall from 740 to 0 under the manifold shift (177 while light tracing's
// vertices were not walked).
TEST(Gvcm, MergesConnectionsAndFailuresAreCounted) {
  struct Case {
    const char* file;
    const char* shift;
  };
  std::map<std::string, uint64_t> orphans;  // photon_parent failures of the caustics box by shift
  for (const Case& c : {Case{"cornell-box.xml", "hybrid"}, Case{"cornell-box-caustics.xml", "hybrid"},
                        Case{"cornell-box-caustics.xml", "manifold"}}) {
    const std::string file = c.file;
    const bool delta_parents = file == "cornell-box-caustics.xml", walks = std::string(c.shift) == "manifold";
    Scene scene = test::project_scene(file, 24);
    Stats stats;
    Context ctx(select_device(""), &stats);
    test::SceneOnDevice on_device(scene, &stats, ctx);
    gvcm(on_device.inputs(), IntegratorParams(std::map<std::string, std::string>{{"shift", c.shift}}))
        ->render_gradients(consistency_settings(2, 7));
    EXPECT_GT(stats.count("gpm/merges"), 0u) << file;
    EXPECT_GT(stats.count("gbdpt/connections"), 0u) << file;
    if (!walks) EXPECT_EQ(stats.count("shift_failures/photon_parent") > 0, delta_parents) << file;
    EXPECT_EQ(stats.count("rays/photon_reverse") > 0, walks) << file << " " << c.shift;
    EXPECT_EQ(stats.count("samples/nonfinite_rejected"), 0u) << file;
    if (delta_parents) orphans[c.shift] = stats.count("shift_failures/photon_parent");
  }
  EXPECT_LT(2 * orphans["manifold"], orphans["hybrid"]);
}

TEST(Gvcm, ParametersAreChecked) {
  using Values = std::map<std::string, std::string>;
  EXPECT_THROW(gvcm_settings(IntegratorParams(Values{{"shift", "bent"}})), Error);
  EXPECT_EQ(gvcm_settings(IntegratorParams(Values{{"shift", "replay"}})).shift, GPT_SHIFT_REPLAY);
  EXPECT_EQ(gvcm_settings(IntegratorParams(Values{{"shift", "manifold"}})).shift, GPT_SHIFT_MANIFOLD);
  EXPECT_THROW(gvcm_photon_settings(IntegratorParams(Values{{"radius", "0"}})), Error);
  EXPECT_EQ(gvcm_photon_settings(IntegratorParams{}).options.mis, BIDIR_MIS_BALANCE);
}

}  // namespace
}  // namespace gdr
