// Detailed balance of the primary-sample-space mutations (kernels/mlt/chains.h): chains started
// from exact samples of an analytic target f on [0, 1)^2 (kernels/tests/mlt_test.cl) must still
// be distributed as f after K steps, for small steps alone, large steps alone and the default
// mix. Each chain contributes only its final state, so the samples are independent and
// Pearson's chi-square applies: 2^16 chains, 16 x 16 cells, host seed 7, device seed 11,
// false-positive rate 1e-3 per case. Also: states stay in [0, 1), the step counts add up, and
// large steps come with the asked-for probability; with an odd dimension count, the last
// dimension is mutated like the others. States of bidirectional paths, whose length decides which
// dimensions the target reads and the mutations touch (GdrMltParams.lengths), keep their target
// too (the same chi-square over the length-picking dimension and one that only the longer
// length reads).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <random>
#include <string>

#include "bsdf/chi2.h"
#include "integrators/mlt/markov_chains.h"
#include "support/devices.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

constexpr const char* kProgram = "tests/mlt_test.cl";
constexpr size_t kChains = size_t(1) << 16;
constexpr int kCells = 16;

double target(double u, double v) {
  double du = u - 0.3, dv = v - 0.6;
  double f = 0.2 + std::exp(-(du * du + dv * dv) / (2.0 * 0.08 * 0.08));
  if (u > 0.7 && v < 0.4) f += 1.5;
  return f;
}

// Exact samples of the target by rejection (its maximum is below 2.8).
std::vector<float> target_samples(size_t n) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<float> s(2 * n);
  for (size_t c = 0; c < n;) {
    double u = u01(rng), v = u01(rng);
    if (u01(rng) * 2.8 < target(u, v)) {
      s[c] = float(u);
      s[n + c] = float(v);
      ++c;
    }
  }
  return s;
}

// Expected count per cell: the target's integral over the cell (midpoint rule, 32 x 32 points
// per cell) over its integral.
std::vector<double> expected_counts(double n) {
  const int sub = 32;
  std::vector<double> e(kCells * kCells, 0.0);
  double total = 0.0;
  for (int j = 0; j < kCells * sub; ++j) {
    for (int i = 0; i < kCells * sub; ++i) {
      double f = target((i + 0.5) / (kCells * sub), (j + 0.5) / (kCells * sub));
      e[(j / sub) * kCells + i / sub] += f;
      total += f;
    }
  }
  for (double& x : e) x *= n / total;
  return e;
}

// The chains' states (SoA, 2 dimensions) counted per cell.
std::vector<double> cell_counts(const std::vector<float>& s) {
  std::vector<double> observed(kCells * kCells, 0.0);
  for (size_t c = 0; c < kChains; ++c) {
    int i = std::min(int(s[c] * kCells), kCells - 1), j = std::min(int(s[kChains + c] * kCells), kCells - 1);
    observed[j * kCells + i] += 1.0;
  }
  return observed;
}

struct Case {
  const char* name;
  float sigma, large_step;
  int steps;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class MarkovChainsTest : public ::testing::TestWithParam<Case> {};

TEST_P(MarkovChainsTest, KeepTheTargetDistribution) {
  const Case& k = GetParam();
  Context& ctx = test::default_context();
  Scene scene = test::furnace_scene(0.5f, 1.0f, 8);
  KernelFactory kernels(ctx, scene);
  MarkovChains chains(ctx, kernels, kProgram, kChains, 2, MltSettings{k.sigma, k.large_step});
  Kernel f = kernels.make(kProgram, "mlt_test_target");
  chains.current().write(target_samples(kChains));
  f.args(cl_uint(kChains), chains.current(), chains.f_current()).run(kChains);
  for (int it = 0; it < k.steps; ++it) {
    chains.propose(11, uint32_t(it));
    f.args(cl_uint(kChains), chains.proposed(), chains.f_proposed()).run(kChains);
    chains.accept(11, uint32_t(it));
  }
  // The last step's expected-value weights: (1 - a, a) with a in [0, 1].
  for (const cl_float2& w : chains.weights().read()) {
    ASSERT_TRUE(w.s[1] >= 0.0f && w.s[1] <= 1.0f && w.s[0] == 1.0f - w.s[1]) << k.name << ": weights " << w.s[0]
                                                                              << ", " << w.s[1];
  }
  std::vector<cl_uint> n = chains.counts();
  const uint64_t small = n[MLT_COUNTER_SMALL_STEPS], large = n[MLT_COUNTER_LARGE_STEPS];
  const uint64_t accepted = uint64_t(n[MLT_COUNTER_SMALL_ACCEPTED]) + n[MLT_COUNTER_LARGE_ACCEPTED];
  ASSERT_EQ(small + large, uint64_t(kChains) * k.steps) << k.name;
  EXPECT_GT(accepted, 0u) << k.name << ": no step was accepted";
  EXPECT_LT(accepted, small + large) << k.name << ": every step was accepted";
  // The large-step count is binomial(steps * chains, large_step): |z| < 4.
  double trials = double(small + large), p = k.large_step;
  if (p > 0.0 && p < 1.0) {
    EXPECT_LT(std::fabs(double(large) - trials * p) / std::sqrt(trials * p * (1 - p)), 4.0) << k.name;
  } else {
    EXPECT_EQ(large, p > 0.0 ? uint64_t(trials) : 0u) << k.name;
  }

  std::vector<float> s = chains.current().read();
  for (size_t c = 0; c < kChains; ++c) {
    float u = s[c], v = s[kChains + c];
    ASSERT_TRUE(u >= 0.0f && u < 1.0f && v >= 0.0f && v < 1.0f) << k.name << ": chain " << c << " left [0, 1)^2";
  }
  test::Chi2Result r = test::chi2_test(cell_counts(s), expected_counts(double(kChains)), double(kChains));
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_GT(r.p_value, 1e-3) << k.name << ": chi2 = " << r.statistic << ", dof = " << r.dof;
}

// Small steps of sigma 0.1 move a chain across a cell in a few steps, so 64 steps leave no chain
// where it started; the default sigma (0.01) keeps the chains near their starts, the mix and the
// large steps alone move them anywhere.
INSTANTIATE_TEST_SUITE_P(Mutations, MarkovChainsTest,
                         ::testing::Values(Case{"small steps", 0.1f, 0.0f, 64},
                                           Case{"default small steps", 0.01f, 0.0f, 64},
                                           Case{"large steps", 0.01f, 1.0f, 16},
                                           Case{"default mix", 0.01f, 0.3f, 64}),
                         [](const ::testing::TestParamInfo<Case>& i) {
                           std::string s = i.param.name;
                           for (char& ch : s) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return s;
                         });

// A chain that does not keep the target is caught: the same chains, each accepting every
// proposal (the target's ratio ignored), drift towards uniform and fail the test above's
// check. This guards the test's power, not the kernels.
TEST(MarkovChains, AcceptingEveryProposalIsDetected) {
  Context& ctx = test::default_context();
  Scene scene = test::furnace_scene(0.5f, 1.0f, 8);
  KernelFactory kernels(ctx, scene);
  MarkovChains chains(ctx, kernels, kProgram, kChains, 2, MltSettings{0.1f, 0.0f});
  chains.current().write(target_samples(kChains));
  for (int it = 0; it < 64; ++it) {
    chains.propose(11, uint32_t(it));
    // A constant target: every proposal is accepted.
    chains.f_current().fill(1.0f);
    chains.f_proposed().fill(1.0f);
    chains.accept(11, uint32_t(it));
  }
  test::Chi2Result r =
      test::chi2_test(cell_counts(chains.current().read()), expected_counts(double(kChains)), double(kChains));
  EXPECT_LT(r.p_value, 1e-6) << "chi2 = " << r.statistic << ": a chain that ignores the target passed";
}

// Three dimensions (a partial block of four), a constant target (every proposal accepted,
// with the whole weight): one large step leaves every dimension uniform (mean 1/2, |z| < 4), and one small step moves
// every dimension by a Gaussian of sigma (mean |step| = sigma sqrt(2 / pi), |z| < 4).
TEST(MarkovChains, EveryDimensionIsMutatedWithAnOddCount) {
  Context& ctx = test::default_context();
  Scene scene = test::furnace_scene(0.5f, 1.0f, 8);
  KernelFactory kernels(ctx, scene);
  const size_t n = kChains, dims = 3;
  const float sigma = 0.01f;
  for (float large_step : {1.0f, 0.0f}) {
    MarkovChains chains(ctx, kernels, kProgram, n, dims, MltSettings{sigma, large_step});
    std::vector<float> start(n * dims, 0.5f);
    chains.current().write(start);
    chains.f_current().fill(1.0f);
    chains.f_proposed().fill(1.0f);
    chains.propose(13, 0);
    chains.accept(13, 0);
    for (const cl_float2& w : chains.weights().read()) {
      ASSERT_TRUE(w.s[0] == 0.0f && w.s[1] == 1.0f) << "a proposal as likely as its state is taken with weight 1";
    }
    std::vector<float> s = chains.current().read();
    for (size_t d = 0; d < dims; ++d) {
      double sum = 0.0;
      for (size_t c = 0; c < n; ++c) {
        float x = s[d * n + c];
        ASSERT_TRUE(x >= 0.0f && x < 1.0f) << "dimension " << d << " of chain " << c << ": " << x;
        sum += large_step > 0.0f ? x : std::fabs(x - 0.5);
      }
      double mean = sum / n;
      double expect = large_step > 0.0f ? 0.5 : sigma * std::sqrt(2.0 / M_PI);
      double sd = large_step > 0.0f ? std::sqrt(1.0 / 12.0 / n) : sigma * std::sqrt((1.0 - 2.0 / M_PI) / n);
      EXPECT_LT(std::fabs(mean - expect) / sd, 4.0)
          << (large_step > 0.0f ? "large" : "small") << " step, dimension " << d << ": mean " << mean;
    }
  }
}

// States of paths of one or two segments (24 dimensions: shared/sampler_types.h gives length 1
// its first 16): dimension 0 picks the length, the target reads dimension 20 only at length 2
// (kernels/tests/mlt_test.cl), where it has a peak. A state of length 1 does not hold dimension
// 20 (a step to length 2 draws it fresh; the test starts such states with 0.1 there). Chains
// started from exact samples keep the target after
// 64 steps: chi-square over 8 cells of u0 for length 1 and 8 x 16 cells of (u0, u20) for length 2,
// host seed 9, device seed 17, false-positive rate 1e-3 per case; small steps of sigma 0.1 cross
// between the lengths often.
double lengths_density(double u0, double u20) {
  if (u0 < 0.5) return 0.5 * 1.5;
  double d = u20 - 0.7;
  return 1.5 * (1.0 + 3.0 * std::exp(-d * d / (2.0 * 0.05 * 0.05)));
}

// Cell of a state: length 1 by u0 alone (cells 0 .. 7), length 2 by (u0, u20) (8 + 16 x 16 cells,
// of which the 8 x 16 with u0 >= 0.5 are used).
int lengths_cell(double u0, double u20) {
  int i = std::min(int(u0 * kCells), kCells - 1);
  if (u0 < 0.5) return i;
  int j = std::min(int(u20 * kCells), kCells - 1);
  return kCells / 2 + j * (kCells / 2) + (i - kCells / 2);
}

// Runs the cases over `kernel`, a target of states of one or two lengths that picks them (lengths)
// or reports what it read (reported: it writes the dimensions read).
void expect_lengths_keep_the_target(const char* kernel, bool reported) {
  Context& ctx = test::default_context();
  Scene scene = test::furnace_scene(0.5f, 1.0f, 8);
  KernelFactory kernels(ctx, scene);
  const size_t dims = 24;
  const int cells = kCells / 2 + kCells * kCells / 2;
  Kernel f = kernels.make(kProgram, kernel);
  for (MltSettings settings : {MltSettings{0.1f, 0.0f}, MltSettings{0.01f, 0.3f}}) {
    const std::string name = std::string(kernel) + (settings.large_step > 0 ? ", default mix" : ", small steps of 0.1");
    settings.lengths = reported ? 0 : 2;
    settings.reported = reported;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    std::vector<float> start(kChains * dims);
    for (size_t c = 0; c < kChains;) {
      for (size_t d = 0; d < dims; ++d) start[d * kChains + c] = float(u01(rng));
      double u0 = start[c], u5 = start[5 * kChains + c], u20 = start[20 * kChains + c];
      if (u01(rng) * 8.0 >= lengths_density(u0, u20) / 1.5 * (1.0 + u5)) continue;
      // What a length-1 state does not hold is never read: any value must do.
      if (u0 < 0.5) {
        for (size_t d = 16; d < dims; ++d) start[d * kChains + c] = 0.1f;
      }
      ++c;
    }
    MarkovChains chains(ctx, kernels, kProgram, kChains, dims, settings);
    chains.current().write(start);
    auto evaluate = [&](const Buffer<float>& states, Buffer<float>& target, Buffer<cl_uint>& read) {
      if (reported) f.args(cl_uint(kChains), states, target, read).run(kChains);
      else f.args(cl_uint(kChains), states, target).run(kChains);
    };
    evaluate(chains.current(), chains.f_current(), chains.current_read());
    for (int it = 0; it < 64; ++it) {
      chains.propose(17, uint32_t(it));
      evaluate(chains.proposed(), chains.f_proposed(), chains.proposed_read());
      chains.accept(17, uint32_t(it));
    }
    std::vector<float> s = chains.current().read();
    std::vector<double> observed(cells, 0.0), expected(cells, 0.0);
    for (size_t c = 0; c < kChains; ++c) observed[lengths_cell(s[c], s[20 * kChains + c])] += 1.0;
    const int sub = 32;
    double total = 0.0;
    for (int j = 0; j < kCells * sub; ++j) {
      for (int i = 0; i < kCells * sub; ++i) {
        double u0 = (i + 0.5) / (kCells * sub), u20 = (j + 0.5) / (kCells * sub), g = lengths_density(u0, u20);
        expected[lengths_cell(u0, u20)] += g;
        total += g;
      }
    }
    for (double& x : expected) x *= double(kChains) / total;
    test::Chi2Result r = test::chi2_test(observed, expected, double(kChains));
    EXPECT_TRUE(r.error.empty()) << r.error;
    EXPECT_GT(r.p_value, 1e-3) << name << ": chi2 = " << r.statistic << ", dof = " << r.dof;
  }
}

TEST(MarkovChains, PathLengthsReadingFewerDimensionsKeepTheTarget) {
  expect_lengths_keep_the_target("mlt_test_lengths_target", false);
}

// The same states when the target reports what each read instead (G-PT's groups: the depth a
// path reached decides it).
TEST(MarkovChains, ReportedReachKeepsTheTarget) { expect_lengths_keep_the_target("mlt_test_reported_target", true); }

}  // namespace
}  // namespace gdr
