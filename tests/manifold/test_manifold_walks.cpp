// The manifold walks on chains whose specular points have a closed form: a mirror plane (the
// mirror image), a glass slab (Snell's law across parallel faces, a 1-D equation) and a glass
// sphere (a reference shot through the analytic sphere in double). From a base chain of another
// start, each solve must reach the closed form within the tolerance in a few iterations, walk
// back to the base chain, and report a generalized geometry term that agrees with a central
// finite difference of the solution over the end point. Deterministic: no random numbers.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

#include "render/manifold_walks.h"
#include "support/render.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

using V3 = std::array<double, 3>;
V3 sub(V3 a, V3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 add(V3 a, V3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
V3 mul(V3 a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(V3 a, V3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(V3 a, V3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double norm(V3 a) { return std::sqrt(dot(a, a)); }
V3 unit(V3 a) { return mul(a, 1.0 / norm(a)); }

V3 vertex(const Scene& s, int i) { return {s.positions[i].x, s.positions[i].y, s.positions[i].z}; }

// The triangle of `shape` that holds p (nearest to its plane among those whose barycentrics
// contain p's projection), with p's barycentrics.
GdrManifoldPoint locate(const Scene& s, int shape, V3 p) {
  const GdrShape& sh = s.shapes[shape];
  GdrManifoldPoint best{0, 0, 0};
  double best_d = INFINITY;
  for (int t = sh.first_triangle; t < sh.first_triangle + sh.triangle_count; ++t) {
    V3 a = vertex(s, s.triangles[t].v[0]), b = vertex(s, s.triangles[t].v[1]), c = vertex(s, s.triangles[t].v[2]);
    V3 e1 = sub(b, a), e2 = sub(c, a), d = sub(p, a);
    double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), d1 = dot(d, e1), d2 = dot(d, e2);
    double det = d11 * d22 - d12 * d12;
    if (!(det > 0)) continue;
    double b1 = (d22 * d1 - d12 * d2) / det, b2 = (d11 * d2 - d12 * d1) / det;
    const double e = 1e-9;
    if (b1 < -e || b2 < -e || b1 + b2 > 1 + e) continue;
    double dist = std::fabs(dot(d, unit(cross(e1, e2))));
    if (dist < best_d) {
      best_d = dist;
      best = GdrManifoldPoint{cl_uint(t), float(b1), float(b2)};
    }
  }
  EXPECT_LT(best_d, 1e-2) << "no triangle of shape " << shape << " holds the point";
  return best;
}

V3 position(const Scene& s, GdrManifoldPoint q) {
  const GdrTriangle& t = s.triangles[q.prim];
  V3 a = vertex(s, t.v[0]), b = vertex(s, t.v[1]), c = vertex(s, t.v[2]);
  return add(a, add(mul(sub(b, a), q.b1), mul(sub(c, a), q.b2)));
}

// Plates of a diffuse material that hold the chains' rough ends: horizontal squares of side 2
// around (x, y, z) at height y, facing up (+y) or down.
MeshData plate(V3 c, bool up) {
  double h = 1.0;
  std::array<float, 3> a{float(c[0] - h), float(c[1]), float(c[2] - h)}, b{float(c[0] - h), float(c[1]), float(c[2] + h)},
      d{float(c[0] + h), float(c[1]), float(c[2] + h)}, e{float(c[0] + h), float(c[1]), float(c[2] - h)};
  return up ? test::quad_mesh(a, b, d, e) : test::quad_mesh(e, d, b, a);
}

struct ChainScene {
  Scene scene;
  int start_shape = -1, end_shape = -1, specular_shape = -1;
};

struct Solver {
  explicit Solver(const ChainScene& s, const ManifoldSettings& settings)
      : on_device(s.scene),
        kernels(on_device.context, s.scene, manifold_defines(on_device.context.device(), settings)),
        walks(on_device.inputs(), kernels, "tests/manifold_test.cl", 64, settings) {}

  std::vector<GdrManifoldResult> solve(const std::vector<GdrManifoldWalk>& w) {
    Buffer<GdrManifoldWalk> in(on_device.context, w);
    Buffer<GdrManifoldResult> out(on_device.context, w.size());
    walks.solve(in, cl_uint(w.size()), out, on_device.device.path_params(RenderSettings{}, 0, 0, 0));
    return out.read();
  }

  test::SceneOnDevice on_device;
  KernelFactory kernels;
  ManifoldWalks walks;
};

GdrManifoldWalk make_walk(const ChainScene& s, V3 start, V3 origin, V3 end, const std::vector<GdrManifoldPoint>& chain,
                          int flags) {
  GdrManifoldWalk w{};
  w.start = locate(s.scene, s.start_shape, start);
  w.origin = locate(s.scene, s.start_shape, origin);
  w.end = locate(s.scene, s.end_shape, end);
  w.count = int(chain.size());
  for (size_t i = 0; i < chain.size(); ++i) {
    w.v[i].at = chain[i];
    w.v[i].flags = flags;
  }
  return w;
}

std::vector<GdrManifoldPoint> points(const ChainScene& s, const std::vector<V3>& p) {
  std::vector<GdrManifoldPoint> out;
  for (const V3& q : p) out.push_back(locate(s.scene, s.specular_shape, q));
  return out;
}

// --- the three chains and their closed forms --------------------------------------------------

// A mirror at y = 0; chains from a plate at y = 1 to one at y = 2.
ChainScene mirror_setup() {
  test::SceneBuilder b;
  int white = b.material(test::diffuse_material(0.5f), "white");
  int mirror = b.material(test::mirror_material(), "mirror");
  ChainScene s;
  s.specular_shape = b.shape(test::quad_mesh({-6, 0, -6}, {-6, 0, 6}, {6, 0, 6}, {6, 0, -6}), mirror, 0, "mirror");
  s.start_shape = b.shape(plate({-1.5, 1, 0}, false), white, 0, "start");
  s.end_shape = b.shape(plate({2.5, 2, 0}, false), white, 0, "end");
  s.scene = b.finish(test::camera_looking_z(0, 1, -5, 30, 8));
  return s;
}
// The mirror point: where the line to the end's mirror image crosses the mirror.
V3 mirror_point(V3 a, V3 e) {
  V3 im{e[0], -e[1], e[2]};
  double t = a[1] / (a[1] - im[1]);
  return add(a, mul(sub(im, a), t));
}

// A glass slab (IOR 1.5) between y = 0.5 and y = 1.5; chains from y = 0 to y = 2.
constexpr double kEta = 1.5;
ChainScene slab_setup() {
  test::SceneBuilder b;
  int white = b.material(test::diffuse_material(0.5f), "white");
  int glass = b.material(test::dielectric_material(BSDF_DIELECTRIC, float(kEta)), "glass");
  ChainScene s;
  s.specular_shape = b.shape(test::box_mesh({-8, 0.5f, -8}, {8, 1.5f, 8}), glass, 0, "slab");
  s.start_shape = b.shape(plate({-1.5, 0, 0}, true), white, 0, "start");
  s.end_shape = b.shape(plate({1.5, 2, 0}, false), white, 0, "end");
  s.scene = b.finish(test::camera_looking_z(0, 1, -9, 30, 8));
  return s;
}
// Entry and exit points: the horizontal run 0.5 tan(a) + 1 tan(g) + 0.5 tan(a) = D with
// sin(a) = eta sin(g), solved by bisection on the angle a in air.
std::vector<V3> slab_points(V3 a, V3 e) {
  V3 d = sub(e, a);
  double run = std::hypot(d[0], d[2]);
  V3 dir = {d[0] / run, 0, d[2] / run};
  auto reach = [](double ta) {
    double sa = std::sin(ta), sg = sa / kEta;
    return std::tan(ta) + sg / std::sqrt(1 - sg * sg);
  };
  double lo = 0, hi = M_PI / 2 - 1e-9;
  for (int i = 0; i < 200; ++i) ((reach(0.5 * (lo + hi)) < run) ? lo : hi) = 0.5 * (lo + hi);
  double ta = 0.5 * (lo + hi), sg = std::sin(ta) / kEta, tg = sg / std::sqrt(1 - sg * sg);
  V3 p1 = add(a, add(mul(dir, 0.5 * std::tan(ta)), V3{0, 0.5, 0}));
  V3 p2 = add(p1, add(mul(dir, tg), V3{0, 1.0, 0}));
  return {p1, p2};
}

// A glass sphere (IOR 1.5, radius 1, smooth normals) at the origin; chains from y = -3 to y = 3.
ChainScene sphere_setup() {
  test::SceneBuilder b;
  int white = b.material(test::diffuse_material(0.5f), "white");
  int glass = b.material(test::dielectric_material(BSDF_DIELECTRIC, float(kEta)), "glass");
  ChainScene s;
  s.specular_shape = b.shape(make_sphere(96, 192), glass, 0, "sphere");
  s.start_shape = b.shape(plate({0, -3, 0}, true), white, 0, "start");
  s.end_shape = b.shape(plate({0, 3, 0}, false), white, 0, "end");
  s.scene = b.finish(test::camera_looking_z(0, 0, -9, 30, 8));
  return s;
}
// Refraction of d at unit normal n (toward the incoming side) with relative IOR e = eta_i / eta_t.
V3 refract(V3 d, V3 n, double e) {
  double c = -dot(d, n), k = 1 - e * e * (1 - c * c);
  return add(mul(d, e), mul(n, e * c - std::sqrt(k)));
}
// The ray from a along d through the analytic sphere: its entry and exit points and where it
// meets the plane y = 3.
std::array<V3, 3> shoot_sphere(V3 a, V3 d) {
  auto hit = [](V3 o, V3 d, bool far) {
    double b = dot(o, d), c = dot(o, o) - 1, disc = std::sqrt(std::max(0.0, b * b - c));
    return add(o, mul(d, far ? -b + disc : -b - disc));
  };
  V3 p1 = hit(a, d, false);
  V3 d1 = unit(refract(d, p1, 1 / kEta));
  V3 p2 = hit(p1, d1, true);
  V3 d2 = unit(refract(d1, mul(p2, -1), kEta));
  return {p1, p2, add(p2, mul(d2, (3 - p2[1]) / d2[1]))};
}
// The ray from a that lands on e, aimed through (u, 0, w) and found by damped Newton steps with
// finite differences (double).
std::vector<V3> sphere_points(V3 a, V3 e) {
  auto land = [&](double u, double w) {
    V3 l = shoot_sphere(a, unit(sub(V3{u, 0, w}, a)))[2];
    return std::array<double, 2>{l[0] - e[0], l[2] - e[2]};
  };
  double u = 0.5 * (a[0] + e[0]), w = 0.5 * (a[2] + e[2]);
  for (int it = 0; it < 100; ++it) {
    auto f = land(u, w);
    double err = std::hypot(f[0], f[1]);
    if (err < 1e-13) break;
    const double h = 1e-7;
    auto fu = land(u + h, w), fw = land(u, w + h);
    double a11 = (fu[0] - f[0]) / h, a12 = (fw[0] - f[0]) / h, a21 = (fu[1] - f[1]) / h, a22 = (fw[1] - f[1]) / h;
    double det = a11 * a22 - a12 * a21;
    double du = -(a22 * f[0] - a12 * f[1]) / det, dw = -(a11 * f[1] - a21 * f[0]) / det;
    for (double t = 1; t > 1e-6; t *= 0.5) {
      auto g = land(u + t * du, w + t * dw);
      if (std::hypot(g[0], g[1]) < err) {
        u += t * du;
        w += t * dw;
        break;
      }
    }
  }
  auto r = shoot_sphere(a, unit(sub(V3{u, 0, w}, a)));
  return {r[0], r[1]};
}

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
    auto omega = [&](int i) { return unit(sub(position(s.scene, r[i].v[0]), position(s.scene, walks[i].start))); };
    V3 du = mul(sub(omega(1), omega(2)), 0.5 / h), dv = mul(sub(omega(3), omega(4)), 0.5 / h);
    double fd = norm(cross(du, dv));
    EXPECT_NEAR(r[0].g_walk / fd, 1.0, 0.01) << c.name << ": g_walk " << r[0].g_walk << ", finite differences " << fd;
  }
}

INSTANTIATE_TEST_SUITE_P(Precision, ManifoldWalkTest, ::testing::Values("float", "double"));

}  // namespace
}  // namespace gdr
