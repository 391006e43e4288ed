// Hard cases for the manifold walks stay finite and are counted: grazing chains, far targets,
// chains at the critical angle (total internal reflection), an index-matched sheet (eta = 1, where the generalized half vector
// vanishes at the solution), vertex normals of zero length and shading normals in the surface's
// plane (a singular frame). Every walk ends in exactly one counted outcome, and its geometry
// terms are finite. Deterministic: no random numbers.
#include <gtest/gtest.h>

#include "support/manifold_chains.h"

namespace gdr {
namespace {

using namespace test;

constexpr int kDelta = MANIFOLD_VERTEX_DELTA, kTransmit = MANIFOLD_VERTEX_TRANSMIT;

// Checks the results and that walks = solved + failures in the stage's counters.
void expect_counted_and_finite(Solver& solver, Stats& stats, const std::vector<GdrManifoldWalk>& walks,
                               const std::vector<GdrManifoldResult>& r, const char* what) {
  for (size_t i = 0; i < r.size(); ++i) {
    EXPECT_TRUE(std::isfinite(r[i].g_walk) && std::isfinite(r[i].g_origin)) << what << " walk " << i;
    EXPECT_GE(r[i].g_walk, 0.0f) << what << " walk " << i;
    EXPECT_TRUE(r[i].status == 0 || (r[i].status >= MANIFOLD_COUNTER_FAIL_NO_CONVERGENCE &&
                                     r[i].status < MANIFOLD_COUNTER_COUNT))
        << what << " walk " << i << ": status " << r[i].status;
  }
  solver.report(&stats);
  uint64_t outcomes = stats.count("manifold/solved");
  for (const char* reason : GDR_COUNTER_NAMES(MANIFOLD_COUNTERS)) {
    if (std::string(reason).find("manifold/fail_") == 0) outcomes += stats.count(reason);
  }
  EXPECT_EQ(stats.count("manifold/walks"), walks.size()) << what;
  EXPECT_EQ(outcomes, walks.size()) << what << ": every walk ends in one counted outcome";
}

TEST(ManifoldStability, GrazingChainsAndFarTargets) {
  // A wide mirror; a start plate just above it (chains leave it at grazing angles) and ends far off.
  SceneBuilder b;
  int white = b.material(diffuse_material(0.5f), "white");
  int mirror = b.material(mirror_material(), "mirror");
  ChainScene s;
  s.specular_shape = b.shape(quad_mesh({-2000, 0, -50}, {-2000, 0, 50}, {2000, 0, 50}, {2000, 0, -50}), mirror, 0, "mirror");
  s.start_shape = b.shape(plate({-1.5, 0.01, 0}, false), white, 0, "start");
  s.end_shape = b.shape(quad_mesh({1990, 2, -10}, {1990, 2, 10}, {-1, 2, 10}, {-1, 2, -10}), white, 0, "end");
  s.scene = b.finish(camera_looking_z(0, 1, -5, 30, 8));
  Stats stats;
  Solver solver(s, ManifoldSettings{}, &stats);
  std::vector<GdrManifoldWalk> walks;
  const V3 origin{-1.5, 0.01, 0};
  for (V3 end : {V3{2.0, 2, 0}, V3{50, 2, 1}, V3{1500, 2, -3}}) {
    for (V3 start : {V3{-1.2, 0.01, 0.3}, V3{-2.4, 0.01, -0.9}}) {
      walks.push_back(make_walk(s, start, origin, end, points(s, {mirror_point(origin, end)}), kDelta));
    }
  }
  auto r = solver.solve(walks);
  expect_counted_and_finite(solver, stats, walks, r, "grazing and far");
}

TEST(ManifoldStability, NearTheCriticalAngle) {
  // Starts inside a glass block under its top face, ends far beyond its edge just above that
  // face: the chains leave the glass at nearly the critical angle, and steps past it meet total
  // internal reflection.
  SceneBuilder b;
  int white = b.material(diffuse_material(0.5f), "white");
  int glass = b.material(dielectric_material(BSDF_DIELECTRIC, 1.5f), "glass");
  ChainScene s;
  s.specular_shape = b.shape(box_mesh({-8, 0, -8}, {8, 1, 8}), glass, 0, "block");
  s.start_shape = b.shape(plate({0, 0.2, 0}, true), white, 0, "start");
  s.end_shape = b.shape(quad_mesh({10, 1.05f, -5}, {10, 1.05f, 5}, {60, 1.05f, 5}, {60, 1.05f, -5}), white, 0, "end");
  s.scene = b.finish(camera_looking_z(0, 1, -9, 30, 8));
  Stats stats;
  Solver solver(s, ManifoldSettings{}, &stats);
  std::vector<GdrManifoldWalk> walks;
  const V3 origin{0, 0.2, 0};
  for (V3 end : {V3{12, 1.05, 0}, V3{30, 1.05, 1}, V3{55, 1.05, -2}}) {
    // The base chain: leaves the glass 0.7 units to the side of the origin, at about the critical angle.
    std::vector<GdrManifoldPoint> base = points(s, {{0.7, 1, 0}});
    for (V3 start : {V3{0.3, 0.2, 0.1}, V3{-0.9, 0.2, 0.8}}) walks.push_back(make_walk(s, start, origin, end, base, kDelta | kTransmit));
  }
  auto r = solver.solve(walks);
  expect_counted_and_finite(solver, stats, walks, r, "near the critical angle");
}

TEST(ManifoldStability, IndexMatchedSheetIsSolved) {
  // A thin dielectric sheet passes light straight: the solution is the straight line.
  SceneBuilder b;
  int white = b.material(diffuse_material(0.5f), "white");
  int sheet = b.material(dielectric_material(BSDF_THIN_DIELECTRIC, 1.5f), "sheet");
  ChainScene s;
  s.specular_shape = b.shape(quad_mesh({-8, 0.7f, -8}, {-8, 0.7f, 8}, {8, 0.7f, 8}, {8, 0.7f, -8}), sheet, 0, "sheet");
  s.start_shape = b.shape(plate({0, 0, 0}, true), white, 0, "start");
  s.end_shape = b.shape(plate({1, 2, 0}, false), white, 0, "end");
  s.scene = b.finish(camera_looking_z(0, 1, -9, 30, 8));
  Stats stats;
  Solver solver(s, ManifoldSettings{}, &stats);
  const V3 start{0.6, 0, -0.4}, origin{-0.3, 0, 0.2}, end{1.2, 2, 0.3};
  auto on_line = [](V3 a, V3 e) { return add(a, mul(sub(e, a), 0.7 / 2.0)); };
  std::vector<GdrManifoldWalk> walks = {
      make_walk(s, start, origin, end, points(s, {on_line(origin, end)}), kDelta | kTransmit)};
  auto r = solver.solve(walks);
  ASSERT_EQ(r[0].status, 0);
  EXPECT_LT(norm(sub(position(s.scene, r[0].v[0]), on_line(start, end))), 2e-3);
  expect_counted_and_finite(solver, stats, walks, r, "index-matched sheet");
}

TEST(ManifoldStability, DegenerateNormals) {
  // Two mirrors side by side: one with vertex normals of zero length (the geometric normal
  // stands in), one whose shading normals lie in its plane (no manifold frame).
  ChainScene zero = mirror_setup(), in_plane = mirror_setup();
  for (ChainScene* cs : {&zero, &in_plane}) {
    Scene& sc = cs->scene;
    GdrShape& m = sc.shapes[cs->specular_shape];
    m.flags |= SHAPE_HAS_NORMALS;
    for (int t = m.first_triangle; t < m.first_triangle + m.triangle_count; ++t) {
      for (int v : sc.triangles[t].v) sc.normals[v] = cs == &zero ? Vec4{0, 0, 0, 0} : Vec4{1, 0, 0, 0};
    }
  }
  const V3 start{-1.0, 1, 0.2}, origin{-1.6, 1, -0.3}, end{2.2, 2, 0.1};
  {
    Stats stats;
    Solver solver(zero, ManifoldSettings{}, &stats);
    std::vector<GdrManifoldWalk> walks = {
        make_walk(zero, start, origin, end, points(zero, {mirror_point(origin, end)}), kDelta)};
    auto r = solver.solve(walks);
    EXPECT_EQ(r[0].status, 0) << "zero-length normals fall back to the geometric normal";
    expect_counted_and_finite(solver, stats, walks, r, "zero normals");
  }
  {
    Stats stats;
    Solver solver(in_plane, ManifoldSettings{}, &stats);
    std::vector<GdrManifoldWalk> walks = {
        make_walk(in_plane, start, origin, end, points(in_plane, {mirror_point(origin, end)}), kDelta)};
    auto r = solver.solve(walks);
    EXPECT_NE(r[0].status, 0) << "a chain over shading normals in the surface's plane was solved";
    expect_counted_and_finite(solver, stats, walks, r, "normals in the plane");
  }
}

}  // namespace
}  // namespace gdr
