// The shift mappings one vertex at a time, through the kernels: the half-vector copy inverts
// (T^-1(T(x)) = x) with reciprocal Jacobians, each Jacobian matches a finite-difference estimate
// of the shift's change of solid angle, and the pairwise MIS weights of a path sum to one.
// Random configurations from std::mt19937 with fixed seeds; tolerances are numerical (float
// arithmetic), not statistical.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/devices.h"

namespace gdr {
namespace {

struct V3 {
  double x, y, z;
};
V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double len(V3 a) { return std::sqrt(dot(a, a)); }
V3 norm(V3 a) {
  double l = len(a);
  return {a.x / l, a.y / l, a.z / l};
}
cl_float4 f4(V3 v, float w = 0) { return cl_float4{{float(v.x), float(v.y), float(v.z), w}}; }
V3 v3(const cl_float4& f) { return {f.s[0], f.s[1], f.s[2]}; }

// A direction with cos(theta) in [lo, hi] about +z (negative for the lower hemisphere).
V3 random_dir(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(0, 1);
  double z = lo + (hi - lo) * u(rng), phi = 2 * M_PI * u(rng), r = std::sqrt(std::max(0.0, 1 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// Solid angle of the small spherical triangle (a, b, c) (unit vectors): Van Oosterom-Strackee.
double solid_angle(V3 a, V3 b, V3 c) {
  double num = std::fabs(dot(a, cross(b, c)));
  double den = 1 + dot(a, b) + dot(b, c) + dot(c, a);
  return 2 * std::atan2(num, den);
}

struct Case {
  int transmitted;
  float eta;
};

// A direction the base could really have sampled from wo (upper hemisphere): reflection or
// refraction about a microfacet normal near +z. False when the microfacet cannot do it.
bool scatter(const Case& c, V3 wo, V3 m, V3& wi) {
  double ci = dot(wo, m);
  if (ci <= 0) return false;
  if (!c.transmitted) {
    wi = {2 * ci * m.x - wo.x, 2 * ci * m.y - wo.y, 2 * ci * m.z - wo.z};
    return wi.z > 0.05;
  }
  double e = 1.0 / c.eta, k = 1 - e * e * (1 - ci * ci);
  if (k <= 0) return false;
  double a = e * ci - std::sqrt(k);
  wi = {-e * wo.x + a * m.x, -e * wo.y + a * m.y, -e * wo.z + a * m.z};
  return wi.z < -0.05;
}

class HalfVectorShift : public testing::TestWithParam<Case> {};

TEST_P(HalfVectorShift, InvertsWithReciprocalJacobian) {
  const Case c = GetParam();
  std::mt19937 rng(12345);
  const unsigned n = 2000;
  std::vector<cl_float4> in;
  while (in.size() < 4 * n) {
    V3 wo = random_dir(rng, 0.2, 1.0), wi;
    if (!scatter(c, wo, random_dir(rng, 0.7, 1.0), wi)) continue;
    V3 wo_off = norm({wo.x + 0.1 * (rng() % 3 - 1.0), wo.y + 0.1 * (rng() % 3 - 1.0), wo.z});
    in.push_back(f4(wo));
    in.push_back(f4(wi));
    in.push_back(f4(wo_off));
    in.push_back(cl_float4{{float(c.transmitted), c.eta, 0, 0}});
  }
  Context& ctx = test::default_context();
  Kernel k = ctx.program("tests/shift_test.cl")->kernel("shift_half_vector_roundtrip");
  Buffer<cl_float4> bin(ctx, in), bout(ctx, 2 * n);
  Buffer<cl_int> bok(ctx, n);
  k.args(n, bin, bout, bok).run(n);
  std::vector<cl_float4> out = bout.read();
  std::vector<cl_int> ok = bok.read();
  unsigned defined = 0;
  for (unsigned i = 0; i < n; ++i) {
    if (!ok[i]) continue;
    ++defined;
    V3 wi = v3(in[4 * i + 1]), back = v3(out[2 * i + 1]);
    ASSERT_LT(len(sub(norm(wi), back)), 2e-4) << "T^-1(T(x)) != x for case " << i;
    double j = out[2 * i].s[3], jb = out[2 * i + 1].s[3];
    ASSERT_TRUE(std::isfinite(j) && j > 0);
    ASSERT_NEAR(j * jb, 1.0, 2e-3) << "Jacobians of T and T^-1 are not reciprocal";
  }
  // Most configurations must be shiftable (refraction fails only under total internal reflection).
  EXPECT_GT(defined, n / 2);
}

TEST_P(HalfVectorShift, JacobianMatchesFiniteDifferences) {
  const Case c = GetParam();
  std::mt19937 rng(777);
  Context& ctx = test::default_context();
  Kernel k = ctx.program("tests/shift_test.cl")->kernel("shift_half_vector_map");
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    V3 wo = random_dir(rng, 0.3, 1.0);
    V3 wo_off = norm({wo.x + 0.15, wo.y - 0.1, wo.z});
    V3 wi;
    if (!scatter(c, wo, random_dir(rng, 0.7, 1.0), wi)) continue;
    // A small triangle of directions around wi.
    V3 t1 = norm(cross(wi, {0.3, 0.5, 0.8})), t2 = cross(wi, t1);
    const double e = 3e-4;
    // An equilateral triangle centred on wi, so the first-order change of J cancels.
    std::vector<cl_float4> dirs = {f4(wi)};
    for (int v = 0; v < 3; ++v) {
      double a = 2 * M_PI * v / 3, ca = e * std::cos(a), sa = e * std::sin(a);
      dirs.push_back(f4(norm({wi.x + ca * t1.x + sa * t2.x, wi.y + ca * t1.y + sa * t2.y, wi.z + ca * t1.z + sa * t2.z})));
    }
    Buffer<cl_float4> bin(ctx, dirs), bout(ctx, 4);
    k.args(4u, f4(wo), f4(wo_off), c.transmitted, c.eta, bin, bout).run(4);
    std::vector<cl_float4> m = bout.read();
    if (m[0].s[3] == 0 || m[1].s[3] == 0 || m[2].s[3] == 0 || m[3].s[3] == 0) continue;
    double before = solid_angle(v3(dirs[1]), v3(dirs[2]), v3(dirs[3]));
    double after = solid_angle(norm(v3(m[1])), norm(v3(m[2])), norm(v3(m[3])));
    double fd = after / before, j = m[0].s[3];
    // Next to the critical angle the map bends so fast that a float finite difference cannot
    // resolve it; such configurations are left out.
    if (j > 5.0 || j < 0.2) continue;
    EXPECT_NEAR(fd / j, 1.0, 2e-2) << "trial " << trial << ": finite difference " << fd << ", Jacobian " << j;
    ++checked;
  }
  EXPECT_GT(checked, 50);  // configurations under total internal reflection are skipped
}

INSTANTIATE_TEST_SUITE_P(Lobes, HalfVectorShift,
                         testing::Values(Case{0, 1.5f}, Case{1, 1.5f}, Case{1, 1.0f / 1.33f}));

TEST(ReconnectionShift, JacobianMatchesFiniteDifferences) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<cl_float4> in;
  std::vector<double> expected;
  for (int trial = 0; trial < 200; ++trial) {
    V3 x = {u(rng), u(rng), 2 + u(rng)}, y = {u(rng), u(rng), 2 + u(rng)};
    V3 z = {u(rng), u(rng), 0}, n = norm({0.2 * u(rng), 0.2 * u(rng), 1});
    // Move z over a small triangle on its tangent plane; compare solid angles seen from y and x.
    V3 t1 = norm(cross(n, {1, 0, 0})), t2 = cross(n, t1);
    const double e = 1e-3;
    V3 zs[3] = {z, {z.x + e * t1.x, z.y + e * t1.y, z.z + e * t1.z}, {z.x + e * t2.x, z.y + e * t2.y, z.z + e * t2.z}};
    V3 dx[3], dy[3];
    for (int i = 0; i < 3; ++i) {
      dx[i] = norm(sub(zs[i], x));
      dy[i] = norm(sub(zs[i], y));
    }
    expected.push_back(solid_angle(dy[0], dy[1], dy[2]) / solid_angle(dx[0], dx[1], dx[2]));
    in.push_back(f4(x));
    in.push_back(f4(y));
    in.push_back(f4(z));
    in.push_back(f4(n));
  }
  Context& ctx = test::default_context();
  Kernel k = ctx.program("tests/shift_test.cl")->kernel("shift_reconnect_jacobian");
  unsigned n = unsigned(expected.size());
  Buffer<cl_float4> bin(ctx, in);
  Buffer<cl_float> bout(ctx, n);
  k.args(n, bin, bout).run(n);
  std::vector<cl_float> j = bout.read();
  for (unsigned i = 0; i < n; ++i) EXPECT_NEAR(j[i] / expected[i], 1.0, 1e-2) << "trial " << i;
}

// The two techniques' shifts give a path different partners (a half-vector copy under BSDF
// sampling, a reconnection to the light point under light sampling), with unrelated ratios.
TEST(PairwiseMis, WeightsSumToOneWhenTheTechniquesPairDifferently) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> lu(-6, 6);  // pdfs and ratios over 12 orders of magnitude
  const unsigned n = 5000;
  std::vector<cl_float2> pdfs, ratio;
  for (unsigned i = 0; i < n; ++i) {
    float q_zero = (i % 5 == 0) ? 0.0f : 1.0f;  // delta cases: no second technique
    pdfs.push_back(cl_float2{{float(std::pow(10, lu(rng))), q_zero * float(std::pow(10, lu(rng)))}});
    ratio.push_back(cl_float2{{float(std::pow(10, lu(rng))), float(std::pow(10, lu(rng)))}});
  }
  Context& ctx = test::default_context();
  Kernel k = ctx.program("tests/shift_test.cl")->kernel("shift_weights_sum");
  Buffer<cl_float2> bp(ctx, pdfs), br(ctx, ratio);
  Buffer<cl_float> bout(ctx, n);
  k.args(n, bp, br, bout).run(n);
  std::vector<cl_float> sums = bout.read();
  for (unsigned i = 0; i < n; ++i) ASSERT_NEAR(sums[i], 1.0f, 1e-4f) << "trial " << i;
}

}  // namespace
}  // namespace gdr
