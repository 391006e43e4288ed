// Emission sampling (kernels/light/emission.h), the first vertex of light subpaths: for every
// emitter type the sampled directions follow the direction pdf (chi-square), which integrates to
// 1; positions are uniform on an area light's triangle and on the scene's bounding disc for
// lights at infinity; the pdfs a sample reports are those the pdf functions give. Every value
// comes from the kernels.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>

#include "bsdf/chi2.h"
#include "image/image_io.h"
#include "render/device_scene.h"
#include "scene/scene_test_files.h"
#include "support/devices.h"

namespace gdr {
namespace {

// A rectangle light (Mitsuba's [-1, 1]^2 at z = 0, normal +z: two triangles split along the
// diagonal from (-1, -1) to (1, 1)), a diffuse floor, and one light of each other type.
const char* kLights = R"(
  <shape type="rectangle"><emitter type="area"><rgb name="radiance" value="2, 3, 4"/></emitter></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/><translate z="-3"/></transform>
    <bsdf type="diffuse"/></shape>
  <emitter type="point"><point name="position" x="0.5" y="1" z="2"/><rgb name="intensity" value="1"/></emitter>
  <emitter type="spot"><transform name="to_world"><lookat origin="0, 0, 4" target="1, 0.5, 0"/></transform>
    <float name="cutoff_angle" value="35"/><float name="beam_width" value="20"/></emitter>
  <emitter type="directional"><vector name="direction" x="1" y="-2" z="-3"/></emitter>
  <emitter type="constant"><rgb name="radiance" value="0.5"/></emitter>)";

struct EmissionKernels {
  explicit EmissionKernels(const Scene& s)
      : scene(s), ctx(test::default_context()), device(ctx, s), program(ctx.program("tests/emission_test.cl")) {
    GdrPtParams p = device.path_params(RenderSettings{}, 0, 0, 1);
    light_count = p.light_count;
    env = p.env_light;
  }
  int light_of_type(int type) const {
    for (size_t i = 0; i < scene.lights.size(); ++i)
      if (scene.lights[i].type == type) return int(i);
    return -1;
  }
  struct Samples {
    std::vector<cl_float4> pos, dir, le, check;
  };
  Samples sample(int index, unsigned seed, unsigned n) {
    Buffer<cl_float4> pos(ctx, n), dir(ctx, n), le(ctx, n), check(ctx, n);
    program->kernel("emission_sample_rng")
        .args(device, light_count, env, index, seed, n, pos, dir, le, check)
        .run(n);
    return {pos.read(), dir.read(), le.read(), check.read()};
  }
  std::vector<float> pdf_dir(int index, cl_float4 normal, const std::vector<cl_float4>& dirs) {
    Buffer<cl_float4> in(ctx, dirs);
    Buffer<float> out(ctx, dirs.size());
    program->kernel("emission_pdf_dir")
        .args(device, light_count, env, index, normal, cl_uint(dirs.size()), in, out)
        .run(dirs.size());
    return out.read();
  }
  const Scene& scene;
  Context& ctx;
  DeviceScene device;
  std::shared_ptr<Program> program;
  int light_count = 0, env = -1;
};

using V3 = std::array<double, 3>;
V3 v3(const cl_float4& v) { return {v.s[0], v.s[1], v.s[2]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 unit(const V3& a) {
  double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}
// An orthonormal frame (s, t, axis).
void frame(const V3& axis, V3* s, V3* t) {
  V3 h = std::fabs(axis[0]) < 0.9 ? V3{1, 0, 0} : V3{0, 1, 0};
  *s = unit(cross(h, axis));
  *t = cross(axis, *s);
}

std::string report(const test::Chi2Result& r) {
  std::ostringstream o;
  o << "chi2 = " << r.statistic << ", dof = " << r.dof << ", p = " << r.p_value << " " << r.error;
  return o.str();
}

// Directions binned in (cos theta, phi) about `axis`, cos theta over [cos_min, 1] in 16 bins and
// phi in 32; expected counts integrate light_emission_pdf_dir over each cell (3 x 3-point
// Gauss-Legendre nodes). No sample may fall below cos_min; the pdf integrates to 1 over the
// cells. False-positive rate 1e-3 (p-value threshold).
void expect_directions_follow_pdf(EmissionKernels& k, int index, const V3& axis, double cos_min, cl_float4 normal,
                                  const EmissionKernels::Samples& got) {
  const int nc = 16, np = 32;
  V3 s, t;
  frame(axis, &s, &t);
  std::vector<double> observed(nc * np, 0.0);
  double n = 0;
  for (size_t i = 0; i < got.dir.size(); ++i) {
    if (got.le[i].s[3] == 0.0f) continue;
    V3 d = v3(got.dir[i]);
    double c = dot(d, axis);
    ASSERT_GE(c, cos_min - 1e-5) << "sample " << i << " left the emission cone";
    int ic = std::clamp(int((c - cos_min) / (1 - cos_min) * nc), 0, nc - 1);
    double phi = std::atan2(dot(d, t), dot(d, s));
    if (phi < 0) phi += 2 * M_PI;
    int ip = std::clamp(int(phi / (2 * M_PI) * np), 0, np - 1);
    observed[ic * np + ip] += 1;
    n += 1;
  }
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, gw[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  std::vector<cl_float4> dirs;
  std::vector<double> weights;
  std::vector<int> cells;
  double hc = (1 - cos_min) / nc, hp = 2 * M_PI / np;
  for (int ic = 0; ic < nc; ++ic)
    for (int ip = 0; ip < np; ++ip)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
          double c = cos_min + (ic + 0.5 + 0.5 * g[a]) * hc, phi = (ip + 0.5 + 0.5 * g[b]) * hp;
          double r = std::sqrt(std::max(0.0, 1 - c * c));
          V3 d;
          for (int j = 0; j < 3; ++j) d[j] = r * std::cos(phi) * s[j] + r * std::sin(phi) * t[j] + c * axis[j];
          dirs.push_back(cl_float4{{float(d[0]), float(d[1]), float(d[2]), 0.0f}});
          weights.push_back(0.25 * hc * hp * gw[a] * gw[b]);
          cells.push_back(ic * np + ip);
        }
  std::vector<float> pdf = k.pdf_dir(index, normal, dirs);
  std::vector<double> expected(nc * np, 0.0);
  double total = 0;
  for (size_t i = 0; i < dirs.size(); ++i) {
    expected[cells[i]] += pdf[i] * weights[i] * n;
    total += pdf[i] * weights[i];
  }
  EXPECT_NEAR(total, 1.0, 1e-3) << "the direction pdf of light " << index << " does not integrate to 1";
  test::Chi2Result r = test::chi2_test(observed, expected, n);
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_GT(r.p_value, 1e-3) << "light " << index << ": " << report(r);
}

// Every sample reports the pdfs the pdf functions give, and a finite emission. The direction's pdf
// is checked to 1e-4; for a lat-long map (`latlong`, in its own frame) to 1e-2 within 0.01 rad of
// its poles (+-y). There a float direction holds its polar angle to only about 1e-7 / sin(theta)
// (1 - |y| is a few ulps): the pdf function, which reads the angle back from the direction, is
// off by that much of the map's slope, while the sample reports the density where it drew it.
void expect_consistent_pdfs(const EmissionKernels::Samples& got, bool delta_dir, bool latlong = false) {
  for (size_t i = 0; i < got.dir.size(); ++i) {
    if (got.le[i].s[3] == 0.0f) continue;
    const double tolerance = latlong && std::fabs(got.dir[i].s[1]) > std::cos(0.01) ? 1e-2 : 1e-4;
    if (!delta_dir) ASSERT_NEAR(got.dir[i].s[3], got.check[i].s[0], tolerance * got.check[i].s[0]) << "sample " << i;
    ASSERT_NEAR(got.pos[i].s[3], got.check[i].s[1], 1e-4 * got.check[i].s[1]) << "sample " << i;
    for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(got.le[i].s[c])) << "sample " << i;
  }
}

// Positions on the disc of radius R about C - dir R facing dir (C, R: the scene's bounding
// sphere): on the disc's plane, inside it, uniform in (r^2 / R^2, phi) on an 8 x 16 grid.
void expect_uniform_on_disc(const GdrLight& l, const EmissionKernels::Samples& got) {
  V3 c{l.position[0], l.position[1], l.position[2]};
  double radius = l.scene_radius;
  std::vector<double> observed(8 * 16, 0.0);
  double n = 0;
  for (size_t i = 0; i < got.pos.size(); ++i) {
    if (got.le[i].s[3] == 0.0f) continue;
    V3 d = v3(got.dir[i]), p = v3(got.pos[i]);
    V3 q{p[0] - (c[0] - d[0] * radius), p[1] - (c[1] - d[1] * radius), p[2] - (c[2] - d[2] * radius)};
    ASSERT_NEAR(dot(q, d), 0.0, 1e-4 * radius) << "sample " << i << " is off the disc's plane";
    double r2 = dot(q, q) / (radius * radius);
    ASSERT_LE(r2, 1.0 + 1e-4) << "sample " << i << " is outside the disc";
    V3 s, t;
    frame(d, &s, &t);
    double phi = std::atan2(dot(q, t), dot(q, s));
    if (phi < 0) phi += 2 * M_PI;
    observed[std::clamp(int(r2 * 8), 0, 7) * 16 + std::clamp(int(phi / (2 * M_PI) * 16), 0, 15)] += 1;
    n += 1;
    ASSERT_NEAR(got.pos[i].s[3], 1.0 / (M_PI * radius * radius), 1e-4 / (M_PI * radius * radius));
  }
  std::vector<double> expected(8 * 16, n / (8 * 16));
  test::Chi2Result r = test::chi2_test(observed, expected, n);
  EXPECT_GT(r.p_value, 1e-3) << "disc positions: " << report(r);
}

constexpr unsigned kSamples = 1000000;

TEST(EmissionSampling, AreaLightPointsAreUniformAndDirectionsCosineWeighted) {
  test::TempFolder folder;
  Scene scene = load_scene(folder.write("scene.xml", test::scene_xml(kLights)));
  EmissionKernels k(scene);
  int index = k.light_of_type(LIGHT_AREA);
  ASSERT_GE(index, 0);
  EmissionKernels::Samples got = k.sample(index, 3u, kSamples);
  expect_consistent_pdfs(got, false);
  expect_directions_follow_pdf(k, index, {0, 0, 1}, 0.0, cl_float4{{0, 0, 1, 0}}, got);
  // The light's triangle is the half of the square below its diagonal (y < x, or the other
  // half: whichever holds the samples); an 8 x 8 grid of the square, diagonal cells halved.
  std::vector<double> observed(64, 0.0);
  double n = 0, below = 0;
  for (size_t i = 0; i < got.pos.size(); ++i) {
    if (got.le[i].s[3] == 0.0f) continue;
    ASSERT_NEAR(got.pos[i].s[2], 0.0, 1e-5);
    ASSERT_NEAR(got.pos[i].s[3], 0.5, 1e-5) << "the triangle's area is 2";
    double x = got.pos[i].s[0], y = got.pos[i].s[1];
    below += y < x;
    observed[std::clamp(int((y + 1) * 4), 0, 7) * 8 + std::clamp(int((x + 1) * 4), 0, 7)] += 1;
    n += 1;
    ASSERT_GT(got.le[i].s[0], 0.0f);
  }
  bool lower = below > 0.5 * n;
  std::vector<double> expected(64, 0.0);
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      double frac = i == j ? 0.5 : ((j < i) == lower ? 1.0 : 0.0);
      expected[j * 8 + i] = n * frac / 32.0;
    }
  test::Chi2Result r = test::chi2_test(observed, expected, n);
  EXPECT_GT(r.p_value, 1e-3) << "triangle positions: " << report(r);
}

TEST(EmissionSampling, PointAndSpotDirectionsFollowTheirPdfs) {
  test::TempFolder folder;
  Scene scene = load_scene(folder.write("scene.xml", test::scene_xml(kLights)));
  EmissionKernels k(scene);
  int point = k.light_of_type(LIGHT_POINT), spot = k.light_of_type(LIGHT_SPOT);
  EmissionKernels::Samples p = k.sample(point, 5u, kSamples);
  expect_consistent_pdfs(p, false);
  for (size_t i = 0; i < 16; ++i) {
    EXPECT_NEAR(p.pos[i].s[0], 0.5, 1e-6);
    EXPECT_NEAR(p.pos[i].s[2], 2.0, 1e-6);
  }
  expect_directions_follow_pdf(k, point, {0, 0, 1}, -1.0, cl_float4{{0, 0, 0, 0}}, p);
  const GdrLight& l = scene.lights[spot];
  EmissionKernels::Samples s = k.sample(spot, 6u, kSamples);
  expect_consistent_pdfs(s, false);
  expect_directions_follow_pdf(k, spot, {l.direction[0], l.direction[1], l.direction[2]}, l.cos_cutoff,
                               cl_float4{{0, 0, 0, 0}}, s);
  // Inside the beam the intensity is the light's; toward the cutoff it falls.
  for (size_t i = 0; i < s.dir.size(); ++i) {
    double c = s.dir[i].s[0] * l.direction[0] + s.dir[i].s[1] * l.direction[1] + s.dir[i].s[2] * l.direction[2];
    if (c > l.cos_falloff + 1e-4) ASSERT_NEAR(s.le[i].s[0], l.radiance[0], 1e-5) << "sample " << i;
    if (c < l.cos_falloff - 1e-4) ASSERT_LT(s.le[i].s[0], l.radiance[0]) << "sample " << i;
  }
}

TEST(EmissionSampling, DirectionalLightsEmitThroughTheSceneDisc) {
  test::TempFolder folder;
  Scene scene = load_scene(folder.write("scene.xml", test::scene_xml(kLights)));
  EmissionKernels k(scene);
  int index = k.light_of_type(LIGHT_DIRECTIONAL);
  const GdrLight& l = scene.lights[index];
  EmissionKernels::Samples got = k.sample(index, 8u, kSamples);
  expect_consistent_pdfs(got, true);
  for (size_t i = 0; i < 64; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(got.dir[i].s[c], l.direction[c]);
  expect_uniform_on_disc(l, got);
}

TEST(EmissionSampling, ConstantEnvironmentIsUniformOverDirectionsAndTheDisc) {
  test::TempFolder folder;
  Scene scene = load_scene(folder.write("scene.xml", test::scene_xml(kLights)));
  EmissionKernels k(scene);
  int index = k.light_of_type(LIGHT_CONSTANT);
  EmissionKernels::Samples got = k.sample(index, 9u, kSamples);
  expect_consistent_pdfs(got, false);
  expect_directions_follow_pdf(k, index, {0, 0, 1}, -1.0, cl_float4{{0, 0, 0, 0}}, got);
  expect_uniform_on_disc(scene.lights[index], got);
}

// The envmap's direction sampling is tested against its pdf in test_environment_map.cpp; here
// the emitted direction is the opposite of an environment sample, with the pdf
// environment_pdf gives it, and the disc is the scene's.
TEST(EmissionSampling, EnvironmentMapEmitsFromItsSampledDirections) {
  test::TempFolder folder;
  Image img(8, 5, {"R", "G", "B"});
  for (size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = 0.2f + 0.1f * float(i % 7);
  write_exr(folder.path("env.exr"), img);
  Scene scene = load_scene(folder.write("scene.xml", test::scene_xml(R"(
    <shape type="rectangle"><bsdf type="diffuse"/></shape>
    <emitter type="envmap"><string name="filename" value="env.exr"/></emitter>)")));
  EmissionKernels k(scene);
  int index = k.light_of_type(LIGHT_ENVMAP);
  EmissionKernels::Samples got = k.sample(index, 10u, 200000);
  expect_consistent_pdfs(got, false, true);
  expect_uniform_on_disc(scene.lights[index], got);
}

}  // namespace
}  // namespace gdr
