// The lat-long environment map follows Mitsuba 3 (src/emitters/envmap.cpp): column c is the
// sample at phi = 2 pi (c + 1/2) / W, row r the sample at theta = pi r / (H - 1) (the first and
// last rows on the poles), bilinear in between. Its importance sampling draws directions with
// exactly the density environment_pdf reports (chi-square), a density that follows the radiance.
// Every value comes from the kernels (kernels/light/envmap.h through kernels/light/lights.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include "bsdf/chi2.h"
#include "image/image_io.h"
#include "render/device_scene.h"
#include "scene/scene_test_files.h"
#include "shared/color.h"
#include "support/devices.h"

namespace gdr {
namespace {

using TexelFn = std::function<void(int c, int r, float* rgb)>;

// A scene whose only emitter is a w x h envmap (scale 2) with texels `texel`; a rectangle so
// that no scene buffer is empty.
Scene envmap_only_scene(const test::TempFolder& folder, int w, int h, const TexelFn& texel) {
  Image img(w, h, {"R", "G", "B"});
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) texel(c, r, &img.pixels[3 * (r * w + c)]);
  write_exr(folder.path("env.exr"), img);
  return load_scene(folder.write("scene.xml", test::scene_xml(R"(
    <shape type="rectangle"><bsdf type="diffuse"/></shape>
    <emitter type="envmap"><string name="filename" value="env.exr"/><float name="scale" value="2"/></emitter>)")));
}

// The map's local frame is the world frame here (no to_world): Mitsuba's lat-long directions.
cl_float4 direction(double u, double v) {
  double theta = M_PI * v, phi = 2 * M_PI * u;
  return cl_float4{{float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)),
                    float(-std::sin(theta) * std::cos(phi)), 0.0f}};
}

struct EnvKernels {
  explicit EnvKernels(const Scene& s)
      : ctx(test::default_context()), device(ctx, s), program(ctx.program("tests/scene_lookup_test.cl")) {
    GdrPtParams p = device.path_params(RenderSettings{}, 0, 0, 1);
    light_count = p.light_count;
    env = p.env_light;
  }
  // (radiance, pdf) along each direction.
  std::vector<cl_float4> lookup(const std::vector<cl_float4>& dirs) {
    Buffer<cl_float4> in(ctx, dirs), out(ctx, dirs.size());
    program->kernel("environment_lookup")
        .args(device, light_count, env, cl_uint(dirs.size()), in, out)
        .run(dirs.size());
    return out.read();
  }
  std::vector<cl_float4> sample(unsigned seed, unsigned n) {
    Buffer<cl_float4> out(ctx, n);
    program->kernel("environment_sample_rng").args(device, light_count, env, seed, n, out).run(n);
    return out.read();
  }
  Context& ctx;
  DeviceScene device;
  std::shared_ptr<Program> program;
  int light_count = 0, env = -1;
};

constexpr int kW = 8, kH = 5;

// Distinct texels; the pole rows are constant along phi (every direction on a pole sees them).
void grid_texel(int c, int r, float* rgb) {
  bool pole = r == 0 || r == kH - 1;
  rgb[0] = pole ? 3.0f + r : 1.0f + c + 10.0f * r;
  rgb[1] = pole ? 5.0f : 100.0f + c * r;
  rgb[2] = 0.5f + r;
}

// The lat-long position of a direction is Mitsuba's, u = atan2(x, -z) / 2 pi wrapped to [0, 1) and
// v = acos(y) / pi, to 2e-7 (the kernel's atan2 is a polynomial, the host's reference is in
// double; float rounding alone leaves about 6e-8), on directions all around the sphere: every
// octant, the axes and the diagonals between them, where the polynomial changes branch.
TEST(EnvironmentMap, UvOfDirectionsIsMitsubas) {
  std::vector<cl_float4> dirs;
  for (int k = 0; k <= 64; ++k)
    for (int j = 0; j < 256; ++j) dirs.push_back(direction(j / 256.0 + 1e-4 * (k % 3), (k + 0.5) / 65.0));
  for (float x : {-1.0f, 0.0f, 1.0f})
    for (float z : {-1.0f, 0.0f, 1.0f})
      if (x != 0.0f || z != 0.0f) dirs.push_back(cl_float4{{x, 0.3f, z, 0.0f}});
  Context& ctx = test::default_context();
  Buffer<cl_float4> in(ctx, dirs);
  Buffer<cl_float2> out(ctx, dirs.size());
  ctx.program("tests/scene_lookup_test.cl")->kernel("environment_uv").args(cl_uint(dirs.size()), in, out).run(dirs.size());
  std::vector<cl_float2> uv = out.read();
  double worst_u = 0, worst_v = 0;
  for (size_t i = 0; i < dirs.size(); ++i) {
    const float* d = dirs[i].s;
    double u = std::atan2(double(d[0]), -double(d[2])) / (2 * M_PI);
    u -= std::floor(u);
    double du = std::fabs(uv[i].s[0] - u);
    worst_u = std::max(worst_u, std::min(du, 1.0 - du));  // u wraps around at 0 and 1
    worst_v = std::max(worst_v, std::fabs(uv[i].s[1] - std::acos(std::clamp(double(d[1]), -1.0, 1.0)) / M_PI));
  }
  EXPECT_LT(worst_u, 2e-7);
  EXPECT_LT(worst_v, 2e-7);
}

TEST(EnvironmentMap, LookupAtGridSamplesReturnsTheirTexels) {
  test::TempFolder folder;
  EnvKernels k(envmap_only_scene(folder, kW, kH, grid_texel));
  std::vector<cl_float4> dirs;
  std::vector<std::array<float, 3>> expected;
  for (int r = 1; r + 1 < kH; ++r) {
    for (int c = 0; c < kW; ++c) {
      dirs.push_back(direction((c + 0.5) / kW, double(r) / (kH - 1)));
      std::array<float, 3> t;
      grid_texel(c, r, t.data());
      expected.push_back(t);
    }
  }
  for (int r : {0, kH - 1}) {
    dirs.push_back(cl_float4{{0.0f, r == 0 ? 1.0f : -1.0f, 0.0f, 0.0f}});
    std::array<float, 3> t;
    grid_texel(0, r, t.data());
    expected.push_back(t);
  }
  std::vector<cl_float4> got = k.lookup(dirs);
  for (size_t i = 0; i < dirs.size(); ++i)
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(got[i].s[ch], 2.0f * expected[i][ch], 2e-3f * expected[i][ch]) << "sample " << i << " channel " << ch;
}

TEST(EnvironmentMap, LookupIsBilinearBetweenSamplesAndWrapsInPhi) {
  test::TempFolder folder;
  EnvKernels k(envmap_only_scene(folder, kW, kH, grid_texel));
  float a[3], b[3], c[3], d[3];
  // Half-way between columns 2 and 3 on row 1; half-way between rows 1 and 2 on column 5; on
  // phi = 0, half-way between the last column and the first.
  std::vector<cl_float4> got = k.lookup({direction(3.0 / kW, 1.0 / (kH - 1)), direction(5.5 / kW, 1.5 / (kH - 1)),
                                         direction(0.0, 2.0 / (kH - 1))});
  grid_texel(2, 1, a);
  grid_texel(3, 1, b);
  grid_texel(5, 1, c);
  grid_texel(5, 2, d);
  float e[3], f[3];
  grid_texel(kW - 1, 2, e);
  grid_texel(0, 2, f);
  for (int ch = 0; ch < 3; ++ch) {
    EXPECT_NEAR(got[0].s[ch], a[ch] + b[ch], 2e-3f * (a[ch] + b[ch])) << "between columns, channel " << ch;
    EXPECT_NEAR(got[1].s[ch], c[ch] + d[ch], 2e-3f * (c[ch] + d[ch])) << "between rows, channel " << ch;
    EXPECT_NEAR(got[2].s[ch], e[ch] + f[ch], 2e-3f * (e[ch] + f[ch])) << "across phi = 0, channel " << ch;
  }
}

// Composite 3-point Gauss-Legendre nodes and weights over [a, b) split into n pieces.
void gauss_nodes(double a, double b, int n, std::vector<double>& x, std::vector<double>& w) {
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double h = (b - a) / n;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      x.push_back(a + (i + 0.5 + 0.5 * g[k]) * h);
      w.push_back(0.5 * h * gw[k]);
    }
}

// A sky of smooth random-looking values, a bright patch, a black region and bright poles, so
// that the tables hold large ratios, zero intervals and nonzero pole rows.
constexpr int kSW = 16, kSH = 9;
void sky_texel(int c, int r, float* rgb) {
  float v = 0.3f + 0.2f * std::sin(1.7f * c + 0.9f * r);
  if (c >= 9 && c <= 10 && r >= 2 && r <= 3) v = 40.0f;
  if (c <= 2 && r >= 4 && r <= 6) v = 0.0f;
  if (r == 0 || r == kSH - 1) v = 2.0f;
  rgb[0] = v;
  rgb[1] = 0.8f * v;
  rgb[2] = 1.2f * v;
}

// 10^6 directions (seed 7, the engine's Philox RNG) binned on the map's own grid cells in
// (u, v): column c from phi at (c + 1/2) / W to (c + 3/2) / W (wrapping), the bands between rows.
// Expected counts integrate environment_pdf (solid angle) over each cell with 3 x 3-point Gauss-
// Legendre rules; cells expected < 5 are pooled. False-positive rate 1e-3.
TEST(EnvironmentMap, SampledDirectionsFollowThePdf) {
  test::TempFolder folder;
  EnvKernels k(envmap_only_scene(folder, kSW, kSH, sky_texel));
  const unsigned n = 1000000;
  const int cells = kSW * (kSH - 1);
  auto cell_of = [](double u, double v) {
    int c = int(std::floor(u * kSW - 0.5));
    c = ((c % kSW) + kSW) % kSW;
    int r = std::min(kSH - 2, std::max(0, int(v * (kSH - 1))));
    return r * kSW + c;
  };
  std::vector<double> observed(cells, 0.0);
  for (const cl_float4& d : k.sample(7u, n)) {
    double len = std::sqrt(double(d.s[0]) * d.s[0] + double(d.s[1]) * d.s[1] + double(d.s[2]) * d.s[2]);
    ASSERT_NEAR(len, 1.0, 1e-4);
    double u = std::atan2(double(d.s[0]), -double(d.s[2])) / (2 * M_PI);
    u -= std::floor(u);
    double v = std::acos(std::clamp(double(d.s[1]) / len, -1.0, 1.0)) / M_PI;
    observed[cell_of(u, v)] += 1.0;
  }

  std::vector<double> us, wu, vs, wv;
  for (int c = 0; c < kSW; ++c) gauss_nodes((c + 0.5) / kSW, (c + 1.5) / kSW, 3, us, wu);
  for (int r = 0; r + 1 < kSH; ++r) gauss_nodes(double(r) / (kSH - 1), double(r + 1) / (kSH - 1), 3, vs, wv);
  std::vector<cl_float4> dirs;
  for (double v : vs)
    for (double u : us) dirs.push_back(direction(u, v));
  std::vector<cl_float4> got = k.lookup(dirs);
  std::vector<double> expected(cells, 0.0);
  double total = 0.0;
  for (size_t iv = 0; iv < vs.size(); ++iv) {
    // d(solid angle) = 2 pi^2 sin(theta) du dv
    double jac = 2 * M_PI * M_PI * std::sin(M_PI * vs[iv]) * wv[iv];
    for (size_t iu = 0; iu < us.size(); ++iu) {
      double m = double(got[iv * us.size() + iu].s[3]) * jac * wu[iu] * n;
      expected[cell_of(us[iu] - std::floor(us[iu]), vs[iv])] += m;
      total += m;
    }
  }
  EXPECT_NEAR(total / n, 1.0, 1e-3) << "the pdf does not integrate to 1 over the sphere";
  test::Chi2Result r = test::chi2_test(observed, expected, n);
  std::ostringstream worst;
  for (int i = 0; i < cells; ++i) {
    double z = (observed[i] - expected[i]) / std::sqrt(std::max(expected[i], 1.0));
    if (std::fabs(z) > 4) worst << "\n  cell row " << i / kSW << " column " << i % kSW << ": observed " << observed[i] << ", expected " << expected[i];
  }
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_GT(r.p_value, 1e-3) << "chi2 = " << r.statistic << ", dof = " << r.dof << worst.str();
}

// The sampled density follows the radiance: away from the poles, luminance / pdf stays close
// to the map's total (for a density exactly proportional to the radiance it would be constant).
TEST(EnvironmentMap, PdfFollowsTheRadiance) {
  test::TempFolder folder;
  constexpr int w = 32, h = 17;
  auto texel = [](int c, int r, float* rgb) {
    float v = 1.0f + 0.5f * std::sin(0.9f * c) * std::cos(1.3f * r);
    rgb[0] = rgb[1] = rgb[2] = v;
  };
  EnvKernels k(envmap_only_scene(folder, w, h, texel));
  std::vector<cl_float4> dirs;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) dirs.push_back(direction((i + 0.37) / 64, 0.25 + 0.5 * (j + 0.5) / 64));
  std::vector<cl_float4> got = k.lookup(dirs);
  double lo = 1e30, hi = 0;
  for (const cl_float4& g : got) {
    double ratio = gdr_luminance(g.s[0], g.s[1], g.s[2]) / g.s[3];
    lo = std::min(lo, ratio);
    hi = std::max(hi, ratio);
  }
  EXPECT_LT(hi / lo, 1.1) << "luminance / pdf ranges over [" << lo << ", " << hi << "]";
}

TEST(EnvironmentMap, SmallMapsArePaddedAsMitsubaDoes) {
  test::TempFolder folder;
  // A 1 x 1 map becomes 2 x 3 texels of its value: the same radiance in every direction.
  Scene s = envmap_only_scene(folder, 1, 1, [](int, int, float* rgb) { rgb[0] = 0.5f, rgb[1] = 1.0f, rgb[2] = 1.5f; });
  const GdrTexture& t = s.textures[s.lights.back().texture];
  EXPECT_EQ(t.width, 2);
  EXPECT_EQ(t.height, 3);
  EnvKernels k(s);
  std::vector<cl_float4> got = k.lookup({direction(0.1, 0.0), direction(0.6, 0.3), direction(0.9, 1.0)});
  for (const cl_float4& g : got) {
    EXPECT_NEAR(g.s[0], 1.0f, 1e-5);
    EXPECT_NEAR(g.s[2], 3.0f, 1e-5);
  }
  // Sampled about uniformly (the rows' weights follow the sine of their bands).
  EXPECT_NEAR(got[1].s[3], 1.0 / (4 * M_PI), 0.2 / (4 * M_PI));
}

}  // namespace
}  // namespace gdr
