// The film's sample_border (Mitsuba 0.6: highQualityEdges), false by default as in Mitsuba:
// without it no film sample lies outside the image and a border pixel is the filter-weighted
// mean of the radiance over the part of its footprint inside the image; with it the whole
// footprint counts. The camera sees, directly (max_depth 1), an emitting strip of radiance 1
// covering film columns x in [a, b] (in pixels from the left edge, a < 0: partly or wholly
// outside the image) and every row. Each sample of a pixel in column p then sees the strip with
// probability E = (integral of the filter over [a, b] - p - 1/2, cut to the pixel's range) /
// (integral over the range), computed here by quadrature of Mitsuba's filter definitions.
// Columns 0..2 of 16 rows x 64 spp (seed 11) are z-tested against E at |z| < 4.5 (36 tests;
// family-wise false-positive rate < 1e-3); where E = 0 every pixel must be exactly 0.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "scene/scene_test_files.h"
#include "support/render.h"

namespace gdr {
namespace {

constexpr int kSize = 16, kSpp = 64;
constexpr double kTanHalfFov = 0.36397023426620234;  // tan(20 degrees): fov 40

struct Filter {
  const char* xml;  // the <rfilter> element
  double radius;
  double (*eval)(double t, double r);
};

double box(double t, double r) { return std::fabs(t) <= r ? 1.0 : 0.0; }
double tent(double t, double r) { return std::fmax(0.0, 1.0 - std::fabs(t) / r); }
double gaussian(double t, double r) {
  double s = r / 4;
  return std::fabs(t) <= r ? std::fmax(0.0, std::exp(-t * t / (2 * s * s)) - std::exp(-8.0)) : 0.0;
}

const Filter kFilters[] = {{R"(<rfilter type="box"/>)", 0.5, box},
                           {R"(<rfilter type="tent"/>)", 1.0, tent},
                           {R"(<rfilter type="gaussian"><float name="stddev" value="0.5"/></rfilter>)", 2.0, gaussian}};

double integral(const Filter& f, double lo, double hi) {
  if (!(hi > lo)) return 0.0;
  const int n = 20000;  // midpoint rule: the filters are smooth between their kinks at 0 and r
  double h = (hi - lo) / n, sum = 0.0;
  for (int i = 0; i < n; ++i) sum += f.eval(lo + (i + 0.5) * h, f.radius);
  return sum * h;
}

// Probability that a sample of column p sees film columns [a, b].
double expected_share(const Filter& f, bool sample_border, int p, double a, double b) {
  double c = p + 0.5, lo = -f.radius, hi = f.radius;
  if (!sample_border) {
    lo = std::fmax(lo, -c);
    hi = std::fmin(hi, kSize - c);
  }
  return integral(f, std::fmax(lo, a - c), std::fmin(hi, b - c)) / integral(f, lo, hi);
}

std::string scene_xml(const Filter& f, const std::string& border_param, double a, double b) {
  // Film column x looks along camera-space x = (1 - 2 x / size) tan(fov / 2) at z = 1 (+x left).
  double xa = (1 - 2 * a / kSize) * kTanHalfFov, xb = (1 - 2 * b / kSize) * kTanHalfFov;
  std::ostringstream s;
  s.precision(17);
  s << R"(<integrator type="path"><integer name="max_depth" value="1"/></integrator>
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, 1" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/>)"
    << border_param << f.xml << R"(</film>
  </sensor>
  <shape type="rectangle">
    <transform name="to_world"><scale x=")" << 0.5 * (xa - xb) << R"(" y="10"/><rotate y="1" angle="180"/>
      <translate x=")" << 0.5 * (xa + xb) << R"(" z="1"/></transform>
    <emitter type="area"><rgb name="radiance" value="1"/></emitter>
  </shape>)";
  return s.str();
}

void expect_border_columns(const std::string& border_param, bool sample_border, double a, double b,
                           const std::string& version = "3.0.0") {
  for (const Filter& f : kFilters) {
    test::TempFolder folder;
    Scene scene = load_scene(folder.write("scene.xml", test::scene_xml(scene_xml(f, border_param, a, b), version)));
    ASSERT_EQ(scene.camera.sample_border, sample_border ? 1 : 0);
    RenderSettings rs;
    rs.spp = kSpp;
    rs.seed = 11;
    rs.max_depth = scene.max_depth;
    std::vector<float> rgb = test::render_pt(scene, rs);
    for (int p = 0; p < 3; ++p) {
      double e = expected_share(f, sample_border, p, a, b), mean = 0.0;
      for (int y = 0; y < kSize; ++y) {
        float v = rgb[3 * (y * kSize + p)];
        if (e == 0.0) EXPECT_EQ(v, 0.0f) << f.xml << " column " << p << " row " << y;
        mean += v / kSize;
      }
      double n = double(kSize) * kSpp, sd = std::sqrt(std::fmax(e * (1 - e), 1e-12) / n);
      EXPECT_LT(std::fabs(mean - e) / sd, 4.5) << f.xml << " strip [" << a << ", " << b << "] column " << p
                                               << ": mean " << mean << ", expected " << e;
    }
  }
}

TEST(SampleBorder, OffByDefaultAnEmitterJustOutsideIsNotSeen) {
  expect_border_columns("", false, -1.2, -0.05);
}

TEST(SampleBorder, OnTheBorderColumnSeesAnEmitterJustOutside) {
  expect_border_columns(R"(<boolean name="sample_border" value="true"/>)", true, -1.2, -0.05);
}

TEST(SampleBorder, OffABorderPixelIsTheMeanOverItsFootprintInside) {
  expect_border_columns(R"(<boolean name="sample_border" value="false"/>)", false, -1.0, 0.8);
}

TEST(SampleBorder, MitsubaZeroSixHighQualityEdges) {
  expect_border_columns(R"(<boolean name="highQualityEdges" value="true"/>)", true, -1.0, 0.8, "0.6.0");
}

}  // namespace
}  // namespace gdr
