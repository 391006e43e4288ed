// The reduction of moment sets: the pairwise update joins the sums of squared deviations of
// disjoint sets of samples into those of their union (which a plain sum of them does not), and
// a launcher's process count is read from its environment.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "cluster/ranks.h"
#include "cluster/reduce.h"

namespace gdr::cluster {
namespace {

struct Set {
  double n = 0, sum = 0, m2 = 0;
};

// Two passes over the values: the mean, then the squared deviations from it.
Set direct_moments(const std::vector<double>& x) {
  Set s;
  s.n = double(x.size());
  for (double v : x) s.sum += v;
  const double mean = s.n > 0 ? s.sum / s.n : 0;
  for (double v : x) s.m2 += (v - mean) * (v - mean);
  return s;
}

TEST(Moments, PairwiseUpdateEqualsTheMomentsOfTheUnion) {
  std::mt19937 rng(7);  // fixed seed: the check is exact arithmetic up to rounding, not statistical
  std::lognormal_distribution<double> value(0.0, 1.5);
  for (int trial = 0; trial < 200; ++trial) {
    const int sets = 1 + trial % 5;
    std::vector<double> all;
    Set joined;
    double plain_m2 = 0;
    int nonempty = 0;
    for (int k = 0; k < sets; ++k) {
      std::vector<double> x(size_t(rng() % 9));  // a rank may hold no sample at all
      for (double& v : x) v = value(rng) + 10 * k;  // sets with different means
      all.insert(all.end(), x.begin(), x.end());
      nonempty += x.empty() ? 0 : 1;
      const Set s = direct_moments(x);
      combine_into(joined.n, joined.sum, joined.m2, s.n, s.sum, s.m2);
      plain_m2 += s.m2;
    }
    const Set expect = direct_moments(all);
    ASSERT_EQ(joined.n, expect.n);
    EXPECT_NEAR(joined.sum, expect.sum, 1e-12 * (1 + std::abs(expect.sum)));
    EXPECT_NEAR(joined.m2, expect.m2, 1e-10 * (1 + expect.m2)) << "trial " << trial;
    // The spread between the sets' means is what a plain sum of m2 leaves out.
    if (nonempty > 1) EXPECT_LT(plain_m2, 0.99 * expect.m2) << "trial " << trial;
  }
}

TEST(Moments, OneRankReducesToItself) {
  Moments m{3, {1.0f, 2.0f}, {0.5f, 0.25f}};
  std::vector<float> v = {4.0f, 5.0f};
  combine_to_root(m, nullptr);
  sum_to_root(v, nullptr);
  EXPECT_EQ(m.passes, 3);
  EXPECT_EQ(m.sum, (std::vector<float>{1.0f, 2.0f}));
  EXPECT_EQ(m.m2, (std::vector<float>{0.5f, 0.25f}));
  EXPECT_EQ(v, (std::vector<float>{4.0f, 5.0f}));
}

TEST(Launcher, ProcessCountIsReadFromOpenMpiOrMpichEnvironment) {
  auto with = [](std::map<std::string, std::string> env) {
    return launched_processes([&env](const char* name) -> const char* {
      auto it = env.find(name);
      return it == env.end() ? nullptr : it->second.c_str();
    });
  };
  EXPECT_EQ(with({}), 1);
  EXPECT_EQ(with({{"OMPI_COMM_WORLD_SIZE", "4"}}), 4);
  EXPECT_EQ(with({{"PMI_SIZE", "3"}}), 3);
  EXPECT_EQ(with({{"OMPI_COMM_WORLD_SIZE", "1"}}), 1);
  EXPECT_EQ(with({{"OMPI_COMM_WORLD_SIZE", "two"}}), 1);
}

}  // namespace
}  // namespace gdr::cluster
