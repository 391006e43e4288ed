// The fast solvers reach the objective of the published baseline (L2: 50 CG iterations; L1: 20
// rounds of 50 CG iterations) or a lower one, on render-like inputs: Gaussian noise plus sparse
// bright outliers (fireflies) in the primal and the gradients. Deterministic (fixed seeds).
#include <gtest/gtest.h>

#include <random>

#include "recon/reconstruct.h"
#include "recon_fixtures.h"
#include "support/devices.h"

namespace gdr {
namespace {

// One value in `every` becomes a positive outlier of up to `size` (seeded).
void add_fireflies(std::vector<float>& v, int every, float size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, every - 1);
  std::uniform_real_distribution<float> amount(0.0f, size);
  for (float& x : v) {
    if (pick(rng) == 0) x += amount(rng);
  }
}

test::GradientImage render_like(int w, int h, unsigned seed) {
  test::GradientImage g = test::exact_problem(w, h);
  test::add_gaussian_noise(g.primal, 0.1f, seed);
  test::add_gaussian_noise(g.dx, 0.05f, seed + 1);
  test::add_gaussian_noise(g.dy, 0.05f, seed + 2);
  add_fireflies(g.primal, 200, 20.0f, seed + 3);
  add_fireflies(g.dx, 300, 10.0f, seed + 4);
  add_fireflies(g.dy, 300, 10.0f, seed + 5);
  return g;
}

TEST(ReconFastObjective, ReachesThePublishedBaseline) {
  // Seeds 21..26 and 31..36.
  for (auto [w, h, seed] : std::vector<std::tuple<int, int, unsigned>>{{160, 96, 21}, {97, 131, 31}}) {
    test::GradientImage g = render_like(w, h, seed);
    for (ReconNorm norm : {ReconNorm::L1, ReconNorm::L2}) {
      SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + (norm == ReconNorm::L1 ? " L1" : " L2"));
      ReconSettings s;
      s.norm = norm;
      s.solver = ReconSettings::Solver::CG;
      ReconResult base = reconstruct(test::default_context(), w, h, g.primal, g.dx, g.dy, s, nullptr);
      s.solver = ReconSettings::Solver::Fast;
      ReconResult fast = reconstruct(test::default_context(), w, h, g.primal, g.dx, g.dy, s, nullptr);
      // float sums over ~10^4 pixels: allow their rounding, nothing more.
      EXPECT_LE(fast.energy, base.energy * (1.0 + 1e-5)) << "baseline " << base.energy;
      if (norm == ReconNorm::L1) EXPECT_LT(fast.iterations, base.iterations / 4);
    }
  }
}

}  // namespace
}  // namespace gdr
