// The manifold walks on chains whose specular points have a closed form: a mirror plane (the
// mirror image), a glass slab (Snell's law across parallel faces, a 1-D equation) and a glass
// sphere (a reference shot through the analytic sphere in double). From a base chain of another
// start, each solve must reach the closed form within the tolerance in a few iterations, walk
// back to the base chain, and report generalized geometry terms that agree with central finite
// differences of the solution over the end point and over the start point. Deterministic: no random
// numbers.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

#include "support/manifold_chains.h"

namespace gdr {
namespace {

using namespace test;

// --- checks --------------------------------------------------------------------------------

struct Case {
  const char* name;
  std::function<ChainScene()> setup;
  std::function<std::vector<V3>(V3, V3)> closed_form;
  int flags;
  V3 start, origin, end;
  double position_tolerance;  // of the solution against the closed form (tessellation included)
};

std::vector<Case> cases() {
  return {
      {"mirror", mirror_setup, [](V3 a, V3 e) { return std::vector<V3>{mirror_point(a, e)}; }, MANIFOLD_VERTEX_DELTA,
       {-1.0, 1, 0.2}, {-1.6, 1, -0.3}, {2.2, 2, 0.1}, 2e-3},
      {"glass slab", slab_setup, slab_points, MANIFOLD_VERTEX_DELTA | MANIFOLD_VERTEX_TRANSMIT, {-1.2, 0, 0.3},
       {-1.8, 0, -0.2}, {1.4, 2, 0.2}, 2e-3},
      // The mesh sphere differs from the analytic one by up to 5e-4 of its radius.
      {"glass sphere", sphere_setup, sphere_points, MANIFOLD_VERTEX_DELTA | MANIFOLD_VERTEX_TRANSMIT,
       {0.25, -3, -0.15}, {-0.2, -3, 0.3}, {0.1, 3, 0.2}, 5e-3},
  };
}

class ManifoldWalkTest : public ::testing::TestWithParam<std::string> {};

// The solid angle per unit area a direction sweeps, by central differences: omega(1), omega(2)
// with the moved point at +-h along one axis, omega(3), omega(4) along the other.
double swept_solid_angle(const std::function<V3(int)>& omega, double h) {
  V3 du = mul(sub(omega(1), omega(2)), 0.5 / h), dv = mul(sub(omega(3), omega(4)), 0.5 / h);
  return norm(cross(du, dv));
}

ManifoldSettings settings_for(const std::string& precision) {
  ManifoldSettings m;
  m.precision = precision;
  return m;
}

// From the base chain of `origin`, the walk reaches the closed form of `start` in a few
// iterations, and walks back.
TEST_P(ManifoldWalkTest, ReachesTheClosedFormAndWalksBack) {
  for (const Case& c : cases()) {
    ChainScene s = c.setup();
    Solver solver(s, settings_for(GetParam()));
    std::vector<V3> base = c.closed_form(c.origin, c.end), want = c.closed_form(c.start, c.end);
    auto r = solver.solve({make_walk(s, c.start, c.origin, c.end, points(s, base), c.flags)});
    ASSERT_EQ(r[0].status, 0) << c.name << ": the walk failed";
    EXPECT_LE(r[0].iterations, 12) << c.name << ": both walks together";
    for (size_t i = 0; i < want.size(); ++i) {
      EXPECT_LT(norm(sub(position(s.scene, r[0].v[i]), want[i])), c.position_tolerance) << c.name << " vertex " << i;
    }
    EXPECT_GT(r[0].g_walk, 0.0f) << c.name;
    EXPECT_GT(r[0].g_origin, 0.0f) << c.name;
  }
}

// The mirror's generalized geometry term is the unfolded path's: cos at the end / length^2.
TEST_P(ManifoldWalkTest, MirrorGeometryTermIsTheUnfoldedOne) {
  Case c = cases()[0];
  ChainScene s = c.setup();
  Solver solver(s, settings_for(GetParam()));
  auto r = solver.solve({make_walk(s, c.start, c.origin, c.end, points(s, c.closed_form(c.origin, c.end)), c.flags)});
  ASSERT_EQ(r[0].status, 0);
  auto unfolded = [&](V3 a) {
    V3 m = mirror_point(a, c.end);
    V3 d = sub(c.end, m);
    double len = norm(sub(m, a)) + norm(d);
    return std::fabs(unit(d)[1]) / (len * len);
  };
  EXPECT_NEAR(r[0].g_walk / unfolded(c.start), 1.0, 1e-3);
  EXPECT_NEAR(r[0].g_origin / unfolded(c.origin), 1.0, 1e-3);
}

// g_walk = |d omega_0 / dA(end)| against central differences of the solved chain's first
// direction as the end point moves on its plate (which lies in a plane y = const).
TEST_P(ManifoldWalkTest, GeometryTermMatchesFiniteDifferences) {
  for (const Case& c : cases()) {
    ChainScene s = c.setup();
    ManifoldSettings m = settings_for(GetParam());
    // Float positions and directions reach about 1e-6 of the scene's size; double's Newton steps 1e-7.
    m.tolerance = GetParam() == "double" ? 2e-7f : 3e-6f;
    m.reverse_factor = 1e9f;  // the moved ends' chains are not the base chain's
    Solver solver(s, m);
    std::vector<GdrManifoldPoint> base = points(s, c.closed_form(c.start, c.end));
    const double h = 0.02;
    const V3 moves[4] = {{h, 0, 0}, {-h, 0, 0}, {0, 0, h}, {0, 0, -h}};
    std::vector<GdrManifoldWalk> walks = {make_walk(s, c.start, c.start, c.end, base, c.flags)};
    for (const V3& d : moves) walks.push_back(make_walk(s, c.start, c.start, add(c.end, d), base, c.flags));
    auto r = solver.solve(walks);
    for (size_t i = 0; i < r.size(); ++i) ASSERT_EQ(r[i].status, 0) << c.name << " walk " << i;
    double fd = swept_solid_angle(
        [&](int i) { return unit(sub(position(s.scene, r[i].v[0]), position(s.scene, walks[i].start))); }, h);
    EXPECT_NEAR(r[0].g_walk / fd, 1.0, 0.01) << c.name << ": g_walk " << r[0].g_walk << ", finite differences " << fd;
  }
}

// g_walk_at_end = |d omega_e / dA(x_0)| against central differences of the solved chain's last
// direction, seen from the end, as the start point moves on its plate (x_e fixed).
TEST_P(ManifoldWalkTest, EndGeometryTermMatchesFiniteDifferences) {
  for (const Case& c : cases()) {
    ChainScene s = c.setup();
    ManifoldSettings m = settings_for(GetParam());
    m.tolerance = GetParam() == "double" ? 2e-7f : 3e-6f;
    m.reverse_factor = 1e9f;  // the closed form's chain is not quite the mesh sphere's
    Solver solver(s, m);
    std::vector<GdrManifoldPoint> base = points(s, c.closed_form(c.start, c.end));
    const double h = 0.02;
    const V3 moves[5] = {{0, 0, 0}, {h, 0, 0}, {-h, 0, 0}, {0, 0, h}, {0, 0, -h}};
    std::vector<GdrManifoldWalk> walks;
    for (const V3& d : moves) walks.push_back(make_walk(s, add(c.start, d), c.start, c.end, base, c.flags));
    auto r = solver.solve(walks);
    for (size_t i = 0; i < r.size(); ++i) ASSERT_EQ(r[i].status, 0) << c.name << " walk " << i;
    const size_t last = base.size() - 1;
    double fd = swept_solid_angle([&](int i) { return unit(sub(position(s.scene, r[i].v[last]), c.end)); }, h);
    EXPECT_NEAR(r[0].g_walk_at_end / fd, 1.0, 0.01)
        << c.name << ": g_walk_at_end " << r[0].g_walk_at_end << ", finite differences " << fd;
  }
}

INSTANTIATE_TEST_SUITE_P(Precision, ManifoldWalkTest, ::testing::Values("float", "double"));

}  // namespace
}  // namespace gdr
