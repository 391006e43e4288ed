// Camera importance (kernels/camera/importance.h): a world point projects to the film position
// whose camera ray reaches it; We and the direction pdf are normalized over the directions
// through the image; the area density matches finite differences of the projection; each pixel's
// normalized filter integrates to 1 over the film. The host draws
// the inputs and does the statistics; every value comes from the kernels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "scene/load_scene.h"
#include "support/devices.h"
#include "support/source_scene.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

cl_float4 f4(double x, double y, double z, double w = 0) {
  return cl_float4{{float(x), float(y), float(z), float(w)}};
}

struct CameraKernels {
  CameraKernels() : ctx(test::default_context()), program(ctx.program("tests/camera_test.cl")) {}
  std::vector<cl_float4> round_trip(const GdrCamera& cam, const std::vector<cl_float4>& raster) {
    Buffer<GdrCamera> c(ctx, std::vector<GdrCamera>{cam});
    Buffer<cl_float4> in(ctx, raster), out(ctx, raster.size());
    program->kernel("camera_round_trip").args(c, cl_uint(raster.size()), in, out).run(raster.size());
    return out.read();
  }
  void importance(const GdrCamera& cam, const std::vector<cl_float4>& dirs, std::vector<cl_float4>* raster,
                  std::vector<cl_float4>* we) {
    Buffer<GdrCamera> c(ctx, std::vector<GdrCamera>{cam});
    Buffer<cl_float4> in(ctx, dirs), r(ctx, dirs.size()), w(ctx, dirs.size());
    // Beyond the near clip at every angle inside the view (cos theta > 0.5 there).
    float dist = std::min(3.0f * cam.near_clip + 1e-3f, 0.5f * cam.far_clip);
    program->kernel("camera_importance").args(c, dist, cl_uint(dirs.size()), in, r, w).run(dirs.size());
    *raster = r.read();
    *we = w.read();
  }
  std::vector<cl_float2> area_density(const GdrCamera& cam, const std::vector<cl_float4>& in) {
    Buffer<GdrCamera> c(ctx, std::vector<GdrCamera>{cam});
    Buffer<cl_float4> b_in(ctx, in);
    Buffer<cl_float2> out(ctx, in.size() / 2);
    program->kernel("camera_pdf_area_fd").args(c, cl_uint(in.size() / 2), b_in, out).run(in.size() / 2);
    return out.read();
  }
  std::vector<float> pixel_weights(const GdrCamera& cam, const std::vector<cl_float2>& raster) {
    Buffer<GdrCamera> c(ctx, std::vector<GdrCamera>{cam});
    Buffer<cl_float2> in(ctx, raster);
    Buffer<float> out(ctx, std::vector<float>(size_t(cam.width) * cam.height, 0.0f));
    program->kernel("camera_pixel_weights").args(c, cl_uint(raster.size()), in, out).run(1);
    return out.read();
  }
  Context& ctx;
  std::shared_ptr<Program> program;
};

CameraKernels& kernels() {
  static CameraKernels k;
  return k;
}

// The project's Cornell box camera (a lookat, fov 39.3 on x, square film) and a wide, non-square
// camera turned about two axes.
std::vector<GdrCamera> cameras() {
  std::vector<GdrCamera> out;
  out.push_back(load_scene(test::source_scene("cornell-box.xml")).camera);
  GdrCamera c = test::camera_looking_z(0.3f, -0.2f, 1.5f, 70.0f, 64);
  c.width = 96;
  c.height = 40;
  c.tan_half_fov_y = c.tan_half_fov_x * 40.0f / 96.0f;
  // Rotation by 30 degrees about y, then 20 about x.
  double a = M_PI / 6, b = M_PI / 9;
  double ry[3][3] = {{std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}};
  double rx[3][3] = {{1, 0, 0}, {0, std::cos(b), -std::sin(b)}, {0, std::sin(b), std::cos(b)}};
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) {
      double v = 0;
      for (int j = 0; j < 3; ++j) v += rx[r][j] * ry[j][k];
      c.to_world[4 * r + k] = float(v);
    }
  out.push_back(c);
  return out;
}

TEST(CameraImportance, ProjectionInvertsTheCameraRay) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const GdrCamera& cam : cameras()) {
    std::vector<cl_float4> raster;
    for (int i = 0; i < 4096; ++i) {
      // Distances along the ray between the clip planes (cos theta > 0.5 inside these views).
      double lo = 2.0 * cam.near_clip + 1e-3, hi = std::min(100.0 * lo, 0.5 * double(cam.far_clip));
      raster.push_back(f4(u(rng) * cam.width, u(rng) * cam.height, lo + (hi - lo) * u(rng)));
    }
    std::vector<cl_float4> got = kernels().round_trip(cam, raster);
    for (size_t i = 0; i < raster.size(); ++i) {
      ASSERT_EQ(got[i].s[2], 1.0f) << "point " << i << " at film (" << raster[i].s[0] << ", " << raster[i].s[1]
                                   << ") did not project";
      EXPECT_NEAR(got[i].s[0], raster[i].s[0], 2e-3 * cam.width) << "point " << i;
      EXPECT_NEAR(got[i].s[1], raster[i].s[1], 2e-3 * cam.height) << "point " << i;
    }
  }
}

TEST(CameraImportance, PointsOutsideTheViewDoNotProject) {
  for (const GdrCamera& cam : cameras()) {
    // Behind the camera, and beyond each edge of the film (the box filter's border off).
    std::vector<cl_float4> raster = {f4(0.5 * cam.width, 0.5 * cam.height, -10.0 - 2 * cam.near_clip),
                                     f4(-0.2 * cam.width, 0.5 * cam.height, 10.0 + 2 * cam.near_clip),
                                     f4(1.2 * cam.width, 0.5 * cam.height, 10.0 + 2 * cam.near_clip),
                                     f4(0.5 * cam.width, -0.2 * cam.height, 10.0 + 2 * cam.near_clip),
                                     f4(0.5 * cam.width, 1.2 * cam.height, 10.0 + 2 * cam.near_clip),
                                     // Nearer than the near clip, in the middle of the view.
                                     f4(0.5 * cam.width, 0.5 * cam.height, 0.5 * cam.near_clip)};
    std::vector<cl_float4> got = kernels().round_trip(cam, raster);
    for (size_t i = 0; i < raster.size(); ++i) EXPECT_EQ(got[i].s[2], 0.0f) << "case " << i;
  }
}

// Directions uniform on the sphere (std::mt19937 seed 5, 2^21 of them): the estimates of the
// integrals of We cos theta and of pdf_dir over the directions that reach the film are 1 within
// 5 standard errors (estimated from the same samples; false-positive rate below 1e-6 each).
TEST(CameraImportance, ImportanceAndDirectionPdfIntegrateToOne) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 1 << 21;
  for (const GdrCamera& cam : cameras()) {
    std::vector<cl_float4> dirs(n);
    for (int i = 0; i < n; ++i) {
      double z = 1 - 2 * u(rng), r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * M_PI * u(rng);
      dirs[i] = f4(r * std::cos(phi), r * std::sin(phi), z);
    }
    std::vector<cl_float4> raster, we;
    kernels().importance(cam, dirs, &raster, &we);
    double s_we = 0, s2_we = 0, s_pdf = 0, s2_pdf = 0;
    for (int i = 0; i < n; ++i) {
      double a = 4 * M_PI * we[i].s[0] * raster[i].s[3], b = 4 * M_PI * we[i].s[1];
      s_we += a;
      s2_we += a * a;
      s_pdf += b;
      s2_pdf += b * b;
    }
    double m_we = s_we / n, se_we = std::sqrt((s2_we / n - m_we * m_we) / n);
    double m_pdf = s_pdf / n, se_pdf = std::sqrt((s2_pdf / n - m_pdf * m_pdf) / n);
    EXPECT_NEAR(m_we, 1.0, 5 * se_we) << "integral of We cos theta, standard error " << se_we;
    EXPECT_NEAR(m_pdf, 1.0, 5 * se_pdf) << "integral of pdf_dir, standard error " << se_pdf;
    EXPECT_LT(se_we, 0.02);
  }
}

// Each pixel's normalized filter h_p integrates to 1 over the film (a 1/16-pixel grid of film
// positions, midpoint rule), for each filter, with and without sample_border: a light subpath
// vertex adds to each pixel what pt's samples of that pixel average.
// The area density (camera_pdf_area, whose ratio at two points is the Jacobian of G-BDPT's
// light-tracing shift) against finite differences: the film area a small surface square projects
// to, over its area, is the density times the film's pixel count, for 500 points on each camera's
// rays (film positions, distances, normals: std::mt19937, seed 2015); the tolerance is numerical
// (measured: within 1.7e-4 and 2.6e-4 on the two cameras, 367 and 354 points not grazing).
TEST(CameraImportance, AreaDensityMatchesFiniteDifferences) {
  std::mt19937 rng(2015);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 1);
  for (const GdrCamera& cam : cameras()) {
    // Distances on the scale of the camera's position, so that float positions resolve the squares.
    const double scale = std::hypot(cam.to_world[3], cam.to_world[7], cam.to_world[11]) + 10.0 * cam.near_clip;
    std::vector<cl_float4> in;
    for (int i = 0; i < 500; ++i) {
      in.push_back(f4(cam.width * u(rng), cam.height * u(rng), scale * (0.2 + 3 * u(rng))));
      in.push_back(f4(g(rng), g(rng), g(rng)));
    }
    const std::vector<cl_float2> out = kernels().area_density(cam, in);
    int checked = 0;
    const double pixels = double(cam.width) * cam.height;
    for (const cl_float2& o : out) {
      if (!(o.s[0] > 0.0f) || !(o.s[1] > 0.0f)) continue;  // grazing, or outside the clip range
      EXPECT_NEAR(o.s[1] / (o.s[0] * pixels), 1.0, 1e-3);
      ++checked;
    }
    EXPECT_GT(checked, 125);
  }
}

TEST(CameraImportance, PixelFiltersIntegrateToOneOverTheFilm) {
  GdrCamera cam = test::camera_looking_z(0, 0, 0, 40.0f, 6);
  cam.height = 5;
  for (int filter : {FILTER_BOX, FILTER_TENT, FILTER_GAUSSIAN}) {
    for (int border : {0, 1}) {
      cam.filter = filter;
      cam.filter_radius = filter == FILTER_BOX ? 0.5f : filter == FILTER_TENT ? 1.0f : 2.0f;
      cam.sample_border = border;
      const int k = 16;
      float r = border ? cam.filter_radius : 0.0f;
      std::vector<cl_float2> raster;
      for (int y = 0; y < int((cam.height + 2 * r) * k); ++y)
        for (int x = 0; x < int((cam.width + 2 * r) * k); ++x)
          raster.push_back(cl_float2{{-r + (x + 0.5f) / k, -r + (y + 0.5f) / k}});
      std::vector<float> w = kernels().pixel_weights(cam, raster);
      for (int p = 0; p < cam.width * cam.height; ++p) {
        // Midpoint rule on the tent's and gaussian's kinks: well inside 1e-2.
        EXPECT_NEAR(w[p] / (k * k), 1.0, 1e-2) << "filter " << filter << " border " << border << " pixel " << p;
      }
    }
  }
}

// Each filter's one-axis sampling draws from the filter: over its whole support and cut at an
// image edge, 200000 draws (std::mt19937, seed 77) binned into 40 bins against the filter's
// integral over each bin (midpoint rule on 50 points a bin), chi-square at a false-positive
// rate of 1e-3 per case (critical value 72.1 for 39 degrees of freedom).
TEST(CameraImportance, FilterSamplesFollowTheFilter) {
  Context& ctx = test::default_context();
  std::shared_ptr<Program> program = kernels().program;
  const cl_uint n = 200000, bins = 40, sub = 50;
  std::mt19937 rng(77);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  std::vector<float> u(n);
  for (float& x : u) x = uniform(rng);
  for (int filter : {FILTER_BOX, FILTER_TENT, FILTER_GAUSSIAN}) {
    const float r = filter == FILTER_BOX ? 0.5f : filter == FILTER_TENT ? 1.0f : 2.0f;
    for (float lo : {-r, -0.5f}) {
      const float hi = r, width = (hi - lo) / bins;
      Buffer<cl_float> bu(ctx, u), bt(ctx, n);
      program->kernel("camera_filter_samples").args(filter, r, lo, hi, n, bu, bt).run(n);
      std::vector<double> counts(bins, 0.0);
      for (float t : bt.read()) counts[std::min<size_t>(bins - 1, size_t(std::max(0.0f, (t - lo) / width)))] += 1;
      std::vector<float> points;
      for (cl_uint k = 0; k < bins * sub; ++k) points.push_back(lo + (k + 0.5f) * width / sub);
      Buffer<cl_float> bp(ctx, points), bv(ctx, points.size());
      program->kernel("camera_filter_values").args(filter, r, cl_uint(points.size()), bp, bv).run(points.size());
      std::vector<float> v = bv.read();
      std::vector<double> mass(bins, 0.0);
      double total = 0;
      for (size_t k = 0; k < v.size(); ++k) mass[k / sub] += v[k], total += v[k];
      double chi2 = 0;
      for (cl_uint b = 0; b < bins; ++b) {
        double expected = n * mass[b] / total;
        chi2 += (counts[b] - expected) * (counts[b] - expected) / expected;
      }
      EXPECT_LT(chi2, 72.1) << "filter " << filter << " from " << lo;
    }
  }
}

// The gaussian filter's samples invert its cdf to float precision: the exact cdf (erf in double)
// at each drawn t is within 4e-7 r of the target u times the filter's mass, over the whole support
// and cut at an image edge, for u on a regular grid of 200001 points (both ends included) and for
// radii 2 and 0.75.
TEST(CameraImportance, GaussianFilterSamplesInvertItsCdf) {
  Context& ctx = test::default_context();
  std::shared_ptr<Program> program = kernels().program;
  const cl_uint n = 200001;
  std::vector<float> u(n);
  for (cl_uint i = 0; i < n; ++i) u[i] = std::min(float(double(i) / (n - 1)), 0x1.fffffep-1f);
  for (float r : {2.0f, 0.75f}) {
    // The filter exp(-t^2 / 2 s^2) - exp(-8), s = r / 4, integrated from -r.
    const double s = r / 4.0;
    auto cdf = [&](double t) {
      return s * std::sqrt(M_PI / 2) * (std::erf(t / (s * M_SQRT2)) + std::erf(2 * M_SQRT2)) - std::exp(-8.0) * (t + r);
    };
    for (float lo : {-r, -0.5f * r}) {
      Buffer<cl_float> bu(ctx, u), bt(ctx, n);
      program->kernel("camera_filter_samples").args(int(FILTER_GAUSSIAN), r, lo, r, n, bu, bt).run(n);
      std::vector<float> t = bt.read();
      double worst = 0;
      size_t at = 0;
      for (cl_uint i = 0; i < n; ++i) {
        double target = cdf(lo) + u[i] * (cdf(r) - cdf(lo)), e = std::fabs(cdf(t[i]) - target);
        if (e > worst) worst = e, at = i;
      }
      EXPECT_LT(worst, 4e-7 * r) << "r " << r << " from " << lo << ": u " << u[at] << " gave t " << t[at];
    }
  }
}

}  // namespace
}  // namespace gdr
