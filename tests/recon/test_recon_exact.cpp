// Reconstruction from exact data: the known image is the minimiser of the objective, so every
// norm and solver must return it; and the L2 kernels against an independent dense solve.
#include <gtest/gtest.h>

#include "recon/reconstruct.h"
#include "recon_fixtures.h"
#include "support/devices.h"

namespace gdr {
namespace {

class ReconExact : public ::testing::TestWithParam<test::ReconCase> {};

TEST_P(ReconExact, ExactDataIsAFixedPoint) {
  test::GradientImage g = test::exact_problem(64, 48);
  ReconSettings s = test::converged(GetParam().norm, GetParam().solver);
  ReconResult r = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, s, nullptr);
  EXPECT_LT(test::max_abs_error(r.rgb, g.truth), 1e-4);
}

// A third of the primal is missing (NaN), so the solver starts far from the answer and has to
// rebuild those pixels from the gradients.
TEST_P(ReconExact, HolesInThePrimalAreRebuiltFromGradients) {
  test::GradientImage g = test::exact_problem(64, 48);
  for (size_t p = 0; p < size_t(g.w) * g.h; p += 3) g.primal[p * 3 + p % 3] = NAN;
  Stats stats;
  ReconSettings s = test::converged(GetParam().norm, GetParam().solver);
  ReconResult r = reconstruct(test::default_context(), g.w, g.h, g.primal, g.dx, g.dy, s, &stats);
  EXPECT_LT(test::max_abs_error(r.rgb, g.truth), 2e-3);
  EXPECT_GT(r.iterations, 0);
  EXPECT_LE(r.residual, 1e-5);
  EXPECT_EQ(stats.count("recon/nonfinite_inputs"), (size_t(g.w) * g.h + 2) / 3);
}

// Sizes that are not multiples of the work-group size, and degenerate strips.
TEST_P(ReconExact, OddSizes) {
  for (auto [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {1, 37}, {37, 1}, {7, 5}, {67, 13}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    test::GradientImage g = test::exact_problem(w, h);
    // Drop every other primal pixel but the first, so a strip still has one anchor.
    for (size_t p = 1; p < size_t(w) * h; p += 2) g.primal[p * 3 + 1] = NAN;
    ReconSettings s = test::converged(GetParam().norm, GetParam().solver);
    ReconResult r = reconstruct(test::default_context(), w, h, g.primal, g.dx, g.dy, s, nullptr);
    ASSERT_EQ(r.rgb.size(), size_t(w) * h * 3);
    EXPECT_LT(test::max_abs_error(r.rgb, g.truth), 2e-3);
  }
}

INSTANTIATE_TEST_SUITE_P(Recon, ReconExact, ::testing::ValuesIn(test::all_cases()),
                         [](const auto& info) { return test::case_name(info.param); });

// Random (inconsistent) primal and gradients, so the answer is a genuine compromise.
TEST(ReconDense, KernelL2MatchesDenseSolve) {
  for (auto [w, h] : std::vector<std::pair<int, int>>{{5, 4}, {1, 6}, {3, 1}}) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    std::vector<float> primal(size_t(w) * h * 3, 0.5f), dx(primal.size(), 0.0f), dy(primal.size(), 0.0f);
    test::add_gaussian_noise(primal, 0.5f, 11);  // seed 11
    test::add_gaussian_noise(dx, 0.3f, 12);      // seed 12
    test::add_gaussian_noise(dy, 0.3f, 13);      // seed 13
    const float alpha = 0.2f;
    std::vector<float> expected = test::dense_l2_solve(w, h, alpha, primal, dx, dy);
    for (auto solver : {ReconSettings::Solver::CG, ReconSettings::Solver::Fast}) {
      ReconSettings s = test::converged(ReconNorm::L2, solver);
      s.alpha = alpha;
      ReconResult r = reconstruct(test::default_context(), w, h, primal, dx, dy, s, nullptr);
      EXPECT_LT(test::max_abs_error(r.rgb, expected), 1e-4);
      // The baseline's fixed budget of 50 iterations is plenty for 20 unknowns.
      ReconSettings published;
      published.norm = ReconNorm::L2;
      published.solver = solver;
      r = reconstruct(test::default_context(), w, h, primal, dx, dy, published, nullptr);
      EXPECT_LT(test::max_abs_error(r.rgb, expected), 1e-3);
    }
  }
}

}  // namespace
}  // namespace gdr
