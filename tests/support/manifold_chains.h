// Specular chains for the manifold walks' tests: scenes built in code (a mirror plane, a glass
// slab, a glass sphere between two diffuse plates) with the closed forms of their specular points,
// walks placed by position, and the solver stage driven on them.
#pragma once
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/manifold_walks.h"
#include "support/render.h"
#include "support/test_scenes.h"

namespace gdr::test {

using V3 = std::array<double, 3>;
inline V3 sub(V3 a, V3 b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline V3 add(V3 a, V3 b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline V3 mul(V3 a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(V3 a, V3 b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline V3 cross(V3 a, V3 b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
inline double norm(V3 a) { return std::sqrt(dot(a, a)); }
inline V3 unit(V3 a) { return mul(a, 1.0 / norm(a)); }

inline V3 vertex(const Scene& s, int i) { return {s.positions[i].x, s.positions[i].y, s.positions[i].z}; }

// The triangle of `shape` that holds p (nearest to its plane among those whose barycentrics
// contain p's projection), with p's barycentrics.
inline GdrManifoldPoint locate(const Scene& s, int shape, V3 p) {
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
  if (!(best_d < 1e-2)) throw std::runtime_error("no triangle of shape " + std::to_string(shape) + " holds the point");
  return best;
}

inline V3 position(const Scene& s, GdrManifoldPoint q) {
  const GdrTriangle& t = s.triangles[q.prim];
  V3 a = vertex(s, t.v[0]), b = vertex(s, t.v[1]), c = vertex(s, t.v[2]);
  return add(a, add(mul(sub(b, a), q.b1), mul(sub(c, a), q.b2)));
}

// Plates of a diffuse material that hold the chains' rough ends: horizontal squares of side 2
// around (x, y, z) at height y, facing up (+y) or down.
inline MeshData plate(V3 c, bool up) {
  double h = 1.0;
  std::array<float, 3> a{float(c[0] - h), float(c[1]), float(c[2] - h)}, b{float(c[0] - h), float(c[1]), float(c[2] + h)},
      d{float(c[0] + h), float(c[1]), float(c[2] + h)}, e{float(c[0] + h), float(c[1]), float(c[2] - h)};
  return up ? quad_mesh(a, b, d, e) : quad_mesh(e, d, b, a);
}

struct ChainScene {
  Scene scene;
  int start_shape = -1, end_shape = -1, specular_shape = -1;
};

// The solver stage on a chain scene, for up to `capacity` walks at once. With `stats`, on a context of its
// own that records into them (the walks' counters among them, after report()).
struct Solver {
  explicit Solver(const ChainScene& s, const ManifoldSettings& settings, Stats* stats = nullptr, size_t capacity = 64)
      : own(stats ? std::make_unique<Context>(select_device(""), stats) : nullptr),
        on_device(s.scene, stats, own ? *own : default_context()),
        kernels(on_device.context, s.scene, manifold_defines(on_device.context.device(), settings)),
        walks(on_device.inputs(), kernels, "tests/manifold_test.cl", capacity, settings) {}

  std::vector<GdrManifoldResult> solve(const std::vector<GdrManifoldWalk>& w) {
    Buffer<GdrManifoldWalk> in(on_device.context, w);
    Buffer<GdrManifoldResult> out(on_device.context, w.size());
    walks.solve(in, cl_uint(w.size()), out, on_device.device.path_params(RenderSettings{}, 0, 0, 0));
    return out.read();
  }
  void report(Stats* stats) { walks.report(stats); }

  std::unique_ptr<Context> own;
  SceneOnDevice on_device;
  KernelFactory kernels;
  ManifoldWalks walks;
};

inline GdrManifoldWalk make_walk(const ChainScene& s, V3 start, V3 origin, V3 end, const std::vector<GdrManifoldPoint>& chain,
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

inline std::vector<GdrManifoldPoint> points(const ChainScene& s, const std::vector<V3>& p) {
  std::vector<GdrManifoldPoint> out;
  for (const V3& q : p) out.push_back(locate(s.scene, s.specular_shape, q));
  return out;
}

// The three chains and their closed forms.

// A mirror at y = 0; chains from a plate at y = 1 to one at y = 2.
inline ChainScene mirror_setup() {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.5f), "white");
  int mirror = b.material(mirror_material(), "mirror");
  ChainScene s;
  s.specular_shape = b.shape(quad_mesh({-6, 0, -6}, {-6, 0, 6}, {6, 0, 6}, {6, 0, -6}), mirror, 0, "mirror");
  s.start_shape = b.shape(plate({-1.5, 1, 0}, false), white, 0, "start");
  s.end_shape = b.shape(plate({2.5, 2, 0}, false), white, 0, "end");
  s.scene = b.finish(camera_looking_z(0, 1, -5, 30, 8));
  return s;
}
// The mirror point: where the line to the end's mirror image crosses the mirror.
inline V3 mirror_point(V3 a, V3 e) {
  V3 im{e[0], -e[1], e[2]};
  double t = a[1] / (a[1] - im[1]);
  return add(a, mul(sub(im, a), t));
}

// A glass slab (IOR 1.5) between y = 0.5 and y = 1.5; chains from y = 0 to y = 2.
inline constexpr double kEta = 1.5;
inline ChainScene slab_setup() {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.5f), "white");
  int glass = b.material(dielectric_material(BSDF_DIELECTRIC, float(kEta)), "glass");
  ChainScene s;
  s.specular_shape = b.shape(box_mesh({-8, 0.5f, -8}, {8, 1.5f, 8}), glass, 0, "slab");
  s.start_shape = b.shape(plate({-1.5, 0, 0}, true), white, 0, "start");
  s.end_shape = b.shape(plate({1.5, 2, 0}, false), white, 0, "end");
  s.scene = b.finish(camera_looking_z(0, 1, -9, 30, 8));
  return s;
}
// Entry and exit points: the horizontal run 0.5 tan(a) + 1 tan(g) + 0.5 tan(a) = D with
// sin(a) = eta sin(g), solved by bisection on the angle a in air.
inline std::vector<V3> slab_points(V3 a, V3 e) {
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

// Two glass slabs (IOR 1.5) between y = 0.5 and 1, and 1.5 and 2; chains of four refractions from
// y = 0 to y = 3.
inline ChainScene double_slab_setup() {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.5f), "white");
  int glass = b.material(dielectric_material(BSDF_DIELECTRIC, float(kEta)), "glass");
  ChainScene s;
  MeshData slabs = box_mesh({-8, 0.5f, -8}, {8, 1, 8}), upper = box_mesh({-8, 1.5f, -8}, {8, 2, 8});
  size_t base = slabs.vertex_count();
  slabs.positions.insert(slabs.positions.end(), upper.positions.begin(), upper.positions.end());
  for (auto i : upper.indices) slabs.indices.push_back(decltype(i)(i + base));
  s.specular_shape = b.shape(slabs, glass, 0, "slabs");
  s.start_shape = b.shape(plate({-1.5, 0, 0}, true), white, 0, "start");
  s.end_shape = b.shape(plate({1.5, 3, 0}, false), white, 0, "end");
  s.scene = b.finish(camera_looking_z(0, 1, -9, 30, 8));
  return s;
}

// A glass sphere (IOR 1.5, radius 1, smooth normals) at the origin; chains from y = -3 to y = 3.
inline ChainScene sphere_setup() {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.5f), "white");
  int glass = b.material(dielectric_material(BSDF_DIELECTRIC, float(kEta)), "glass");
  ChainScene s;
  s.specular_shape = b.shape(make_sphere(96, 192), glass, 0, "sphere");
  s.start_shape = b.shape(plate({0, -3, 0}, true), white, 0, "start");
  s.end_shape = b.shape(plate({0, 3, 0}, false), white, 0, "end");
  s.scene = b.finish(camera_looking_z(0, 0, -9, 30, 8));
  return s;
}
// Refraction of d at unit normal n (toward the incoming side) with relative IOR e = eta_i / eta_t.
inline V3 refract(V3 d, V3 n, double e) {
  double c = -dot(d, n), k = 1 - e * e * (1 - c * c);
  return add(mul(d, e), mul(n, e * c - std::sqrt(k)));
}
// The ray from a along d through the analytic sphere: its entry and exit points and where it
// meets the plane y = 3.
inline std::array<V3, 3> shoot_sphere(V3 a, V3 d) {
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
inline std::vector<V3> sphere_points(V3 a, V3 e) {
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

}  // namespace gdr::test
