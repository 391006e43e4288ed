// Lights at the edges: a tiny (1e-3 wide), very bright (1e8) area light lighting a diffuse plane
// must give the analytic irradiance with no rejected samples; lights that face away from a
// surface, or light a one-sided surface from behind, contribute exactly nothing.
#include <gtest/gtest.h>

#include "bsdf/bsdf_harness.h"
#include "stability/stability_checks.h"
#include "support/test_scenes.h"

namespace gdr::test {
namespace {

constexpr int kSmallLightRes = 24;
constexpr float kFov = 40.0f;
constexpr float kPlaneZ = 10.0f;   // the lit plane z = 10, facing the camera at the origin
constexpr float kHeight = 1.0f;    // lights at distance h in front of the plane
constexpr float kLightX = 4.0f;    // at x = +-4: outside the view, so only their light is seen
constexpr float kSide = 1e-3f, kSmallLightLe = 1e8f, kRho = 0.8f;

// The plane with two tiny lights facing it, symmetric about x = 0 and y = 0 so the expected
// image does not depend on the film's axis directions.
Scene small_light_scene(const GdrMaterial& plane) {
  SceneBuilder b;
  int mat = b.material(plane, "plane");
  int black = b.material(diffuse_material(0.0f), "light body");
  b.shape(quad_mesh({-5, -5, kPlaneZ}, {-5, 5, kPlaneZ}, {5, 5, kPlaneZ}, {5, -5, kPlaneZ}), mat, 0.0f, "plane");
  for (float x : {-kLightX, kLightX}) {
    float z = kPlaneZ - kHeight, s = 0.5f * kSide;
    b.shape(quad_mesh({x - s, -s, z}, {x + s, -s, z}, {x + s, s, z}, {x - s, s, z}), black, kSmallLightLe, "light");
  }
  return b.finish(camera_looking_z(0, 0, 0, kFov, kSmallLightRes));
}

// Expected pixel values: rho / pi * E with the irradiance of a small light E = Le A h^2 / r^4
// (both cosines are h / r), averaged over each pixel's box footprint with 32x32 points.
std::vector<double> expected_image() {
  const double t = std::tan(kFov * 0.5 * M_PI / 180.0), area = double(kSide) * kSide;
  std::vector<double> img;
  const int sub = 32;
  for (int py = 0; py < kSmallLightRes; ++py) {
    for (int px = 0; px < kSmallLightRes; ++px) {
      double sum = 0;
      for (int j = 0; j < sub; ++j) {
        for (int i = 0; i < sub; ++i) {
          double fx = px + (i + 0.5) / sub, fy = py + (j + 0.5) / sub;
          double x = kPlaneZ * (1 - 2 * fx / kSmallLightRes) * t, y = kPlaneZ * (1 - 2 * fy / kSmallLightRes) * t;
          for (double lx : {-kLightX, kLightX}) {
            double r2 = kHeight * kHeight + (x - lx) * (x - lx) + y * y;
            sum += kSmallLightLe * area * kHeight * kHeight / (r2 * r2);
          }
        }
      }
      double radiance = kRho / M_PI * sum / (sub * sub);
      for (int c = 0; c < 3; ++c) img.push_back(radiance);
    }
  }
  return img;
}

// Seed 201, 24x24 pixels x 64 spp (MIS). Pixels are independent, so |z| < 5 on the mean of
// (pixel - expected) has a false-positive rate of 5.7e-7; 1e-3 of the expected mean is added for
// the small-light approximation (relative error ~(side / h)^2 = 1e-6) and the quadrature.
TEST(SmallBrightLight, DiffusePlaneMatchesAnalyticIrradiance) {
  Rendered r = render_checked(small_light_scene(diffuse_material(kRho)), 201, 64, 4);
  ASSERT_TRUE(all_finite(r.rgb));
  EXPECT_EQ(r.nonfinite, 0u);
  std::vector<double> expected = expected_image();
  double expected_mean = 0;
  for (double e : expected) expected_mean += e / double(expected.size());
  double mean = 0, se = 0;
  mean_z(r.rgb, expected, &mean, &se);
  EXPECT_LT(std::fabs(mean), 5 * se + 1e-3 * expected_mean)
      << "mean error " << mean << " (expected mean " << expected_mean << ", se " << se << ")";
  // Each pixel on its own, within 6 sigma of the pixels' spread (luminance is what varies).
  double max_rel = 0;
  for (size_t i = 0; i < expected.size(); ++i) max_rel = std::max(max_rel, std::fabs(r.rgb[i] / expected[i] - 1));
  EXPECT_LT(max_rel, 0.5) << "a pixel is far from its analytic value";
}

// The same lights over near-delta conductors: the BSDF values reach ~1/(pi alpha^2) and the
// light's radiance is 1e8, so samples are huge, but every one must stay finite.
TEST(SmallBrightLight, NearDeltaConductorStaysFinite) {
  for (float alpha : {1e-4f, 1e-6f}) {
    for (int d : {MICROFACET_GGX, MICROFACET_BECKMANN}) {
      Rendered r = render_checked(small_light_scene(conductor_material(BSDF_ROUGH_CONDUCTOR, d, alpha, alpha)),
                                  202, 16, 4);
      EXPECT_TRUE(all_finite(r.rgb)) << "alpha " << alpha << " distribution " << d;
      EXPECT_EQ(r.nonfinite, 0u) << "alpha " << alpha << " distribution " << d;
    }
  }
}

// A light behind the camera facing away from the plane it would light: nothing reaches the film.
TEST(LightFacingAway, ContributesExactlyZero) {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.8f), "white");
  b.shape(quad_mesh({-5, -5, 2}, {-5, 5, 2}, {5, 5, 2}, {5, -5, 2}), white, 0.0f, "plane");
  // Normal -z: it emits away from the plane at z = 2 (the camera at the origin sees its back).
  b.shape(quad_mesh({-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}), white, 100.0f, "light");
  Rendered r = render_checked(b.finish(camera_looking_z(0, 0, 0, 60, 16)), 203, 16);
  EXPECT_EQ(r.nonfinite, 0u);
  for (float v : r.rgb) ASSERT_EQ(v, 0.0f);
}

// A light behind a one-sided diffuse plane, facing the plane's back: the plane's front (seen by
// the camera) receives nothing.
TEST(LightFacingAway, LightBehindOneSidedSurfaceContributesExactlyZero) {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.8f), "white");
  b.shape(quad_mesh({-5, -5, 2}, {-5, 5, 2}, {5, 5, 2}, {5, -5, 2}), white, 0.0f, "plane");
  b.shape(quad_mesh({-1, -1, 3}, {-1, 1, 3}, {1, 1, 3}, {1, -1, 3}), white, 100.0f, "light");  // normal -z
  Rendered r = render_checked(b.finish(camera_looking_z(0, 0, 0, 60, 16)), 204, 16);
  EXPECT_EQ(r.nonfinite, 0u);
  for (float v : r.rgb) ASSERT_EQ(v, 0.0f);
}

}  // namespace
}  // namespace gdr::test
