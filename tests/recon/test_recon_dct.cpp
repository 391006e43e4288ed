// The direct DCT solve of the uniform-weight L2 system against an independent dense solve, and
// its use (or fallback) inside reconstruct().
#include <gtest/gtest.h>

#include <memory>

#include "recon/cg_solver.h"
#include "recon/dct_solver.h"
#include "recon/reconstruct.h"
#include "recon_fixtures.h"
#include "support/devices.h"

namespace gdr {
namespace {

struct RandomProblem {
  std::vector<float> primal, dx, dy;
};

// Random (inconsistent) primal and gradients, so the answer is a genuine compromise.
RandomProblem random_problem(int w, int h, unsigned seed) {
  RandomProblem p;
  p.primal.assign(size_t(w) * h * 3, 0.5f);
  p.dx.assign(p.primal.size(), 0.0f);
  p.dy.assign(p.primal.size(), 0.0f);
  test::add_gaussian_noise(p.primal, 0.5f, seed);
  test::add_gaussian_noise(p.dx, 0.3f, seed + 1);
  test::add_gaussian_noise(p.dy, 0.3f, seed + 2);
  return p;
}

// Heights cover radix 4, 2, 3, 5, a prime (generic butterfly), 1 and composites of them; widths
// include 1 (no x edges) and primes.
TEST(ReconDct, MatchesDenseSolve) {
  const std::vector<std::pair<int, int>> sizes = {{1, 1}, {1, 6},  {6, 1},  {5, 4},  {3, 2},
                                                  {37, 23}, {7, 45}, {8, 16}, {4, 29}, {2, 8}};
  for (auto [w, h] : sizes) {
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    ASSERT_TRUE(DctSolver::supports(h));
    RandomProblem p = random_problem(w, h, 31);  // seeds 31, 32, 33
    for (float alpha : {0.2f, 1.0f}) {
      Context& ctx = test::default_context();
      ReconSystem problem(ctx, w, h, p.primal, p.dx, p.dy);
      problem.set_l2_weights(alpha);
      problem.build_rhs();
      DctSolver(ctx, w, h).solve(problem.system(), alpha);
      std::vector<float> expected = test::dense_l2_solve(w, h, alpha, p.primal, p.dx, p.dy);
      EXPECT_LT(test::max_abs_error(problem.result(nullptr), expected), 2e-4) << "alpha " << alpha;
    }
  }
}

TEST(ReconDct, SupportedHeights) {
  for (int h : {1, 2, 3, 720, 1080, 1024, 61, 2 * 61, 59 * 3}) EXPECT_TRUE(DctSolver::supports(h)) << h;
  for (int h : {0, 67, 2 * 67, 1021}) EXPECT_FALSE(DctSolver::supports(h)) << h;
}

// The fast L2 solve uses the direct solve when every input is finite (no iterations needed) and
// the PCG otherwise or for unsupported heights; all agree with the converged baseline CG.
TEST(ReconDct, ReconstructUsesItOrFallsBack) {
  struct Case {
    int w, h;
    bool hole, direct;
  };
  for (Case c : {Case{37, 23, false, true}, Case{37, 23, true, false}, Case{9, 67, false, false},
                 Case{1, 40, false, true}, Case{40, 1, false, true}}) {
    SCOPED_TRACE(std::to_string(c.w) + "x" + std::to_string(c.h) + (c.hole ? " with NaN" : ""));
    RandomProblem p = random_problem(c.w, c.h, 41);  // seeds 41, 42, 43
    if (c.hole) p.primal[3 * (c.w + 1)] = NAN;
    ReconSettings s;
    s.norm = ReconNorm::L2;
    Stats stats;
    ReconResult fast = reconstruct(test::default_context(), c.w, c.h, p.primal, p.dx, p.dy, s, &stats);
    EXPECT_EQ(fast.iterations == 0, c.direct);
    EXPECT_LE(fast.residual, 1e-4);
    ReconSettings reference = test::converged(ReconNorm::L2, ReconSettings::Solver::CG);
    ReconResult cg = reconstruct(test::default_context(), c.w, c.h, p.primal, p.dx, p.dy, reference, nullptr);
    EXPECT_LT(test::max_abs_error(fast.rgb, cg.rgb), 1e-3);
  }
}

}  // namespace
}  // namespace gdr

namespace gdr {
namespace {

// Deferred timing still records every launch (at the end of reconstruct) and gives the same
// image as waiting on each launch.
TEST(ReconDeferredTiming, RecordsKernelsAndMatchesBlockingRuns) {
  test::GradientImage g = test::exact_problem(33, 21);
  test::add_gaussian_noise(g.primal, 0.2f, 7);  // seed 7
  Stats stats;
  Context ctx(test::default_context().device(), &stats);
  ReconSettings s;  // L1, fast: many launches
  ReconResult deferred = reconstruct(ctx, g.w, g.h, g.primal, g.dx, g.dy, s, nullptr);
  EXPECT_FALSE(ctx.deferred_timing());
  EXPECT_EQ(stats.count("kernel_items/recon_pack"), size_t(g.w) * g.h);
  EXPECT_GT(stats.count("kernel_items/cg_update_p_apply_dot"), 0u);
  // 20 CG iterations with every launch waited on, then with deferred timing: same image.
  std::vector<float> images[2];
  for (int d = 0; d < 2; ++d) {
    ReconSystem problem(ctx, g.w, g.h, g.primal, g.dx, g.dy);
    problem.set_l2_weights(s.alpha);
    problem.build_rhs();
    CgSolver cg(ctx, g.w, g.h);
    std::unique_ptr<DeferredTiming> scope;
    if (d == 1) scope = std::make_unique<DeferredTiming>(ctx);
    cg.solve(problem.system(), 20, 0.0);
    images[d] = problem.result(nullptr);
  }
  EXPECT_EQ(images[0], images[1]);
  EXPECT_TRUE(test::all_finite(deferred.rgb));
}

}  // namespace
}  // namespace gdr
