// Hard geometry and materials inside the white furnace (diffuse albedo 0.5, emission 1, so every
// point sees radiance 2): objects that are invisible in exact arithmetic must stay invisible, and
// nothing may produce a NaN, an Inf or a rejected sample. Objects: zero-area and sliver triangles
// (also as very bright area lights), an index-matched (eta = 1) glass sphere, a glass box whose
// side faces reflect totally, a perfect mirror sphere with near-delta roughness alpha = 1e-4.
// Each test: seed stated below, 24x24 pixels x 64 spp, unbounded depth with Russian roulette;
// |z| < 5 on the image mean (false-positive rate 5.7e-7 per test).
#include <gtest/gtest.h>

#include "bsdf/bsdf_harness.h"
#include "stability/stability_checks.h"
#include "support/test_scenes.h"

namespace gdr::test {
namespace {

constexpr float kAlbedo = 0.5f, kLe = 1.0f;
constexpr int kRes = 24, kSpp = 64;

void expect_furnace_radiance(const Scene& scene, uint32_t seed, const char* what) {
  Rendered r = render_checked(scene, seed, kSpp);
  ASSERT_TRUE(all_finite(r.rgb)) << what;
  EXPECT_EQ(r.nonfinite, 0u) << what;
  const double expected = kLe / (1.0 - kAlbedo);
  double mean = 0, se = 0;
  double z = mean_z(r.rgb, std::vector<double>(r.rgb.size(), expected), &mean, &se);
  EXPECT_LT(std::fabs(z), 5.0) << what << ": mean " << expected + mean << " expected " << expected << " se " << se;
  EXPECT_GT(se, 0.0) << what;
}

// Triangles that have no area: repeated vertices, collinear vertices, and vertices a few ulps
// apart, some of them very bright emitters (a light with zero area emits no power).
TEST(FurnaceObjects, DegenerateTrianglesAndLightsAreInvisible) {
  SceneBuilder b(furnace_scene(kAlbedo, kLe, kRes));
  int white = b.material(diffuse_material(kAlbedo), "white");
  b.shape(triangle_mesh({0, 0, 0.5f}, {0, 0, 0.5f}, {0, 0, 0.5f}), white, 0.0f, "point");
  b.shape(triangle_mesh({-0.5f, 0, 0.5f}, {0, 0, 0.5f}, {0.5f, 0, 0.5f}), white, 0.0f, "collinear");
  b.shape(triangle_mesh({-0.5f, 0.1f, 0.6f}, {-0.5f, 0.1f, 0.6f}, {0.5f, -0.1f, 0.4f}), white, 0.0f, "segment");
  b.shape(triangle_mesh({0.2f, 0.2f, 0.5f}, {0.2f, 0.2f, 0.5f}, {0.2f, 0.2f, 0.5f}), white, 1e6f, "point light");
  b.shape(triangle_mesh({-0.3f, -0.3f, 0.5f}, {0, 0, 0.5f}, {0.3f, 0.3f, 0.5f}), white, 1e6f, "line light");
  expect_furnace_radiance(b.finish(furnace_scene(kAlbedo, kLe, kRes).camera), 101, "degenerate");
}

// A scene whose only light has zero area renders exactly black (and finite).
TEST(FurnaceObjects, OnlyLightDegenerateRendersBlack) {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.8f), "white");
  b.shape(quad_mesh({-1, -1, 2}, {-1, 1, 2}, {1, 1, 2}, {1, -1, 2}), white, 0.0f, "wall");
  b.shape(triangle_mesh({0, 0, 1}, {0.5f, 0, 1}, {1, 0, 1}), white, 1e6f, "line light");
  b.shape(triangle_mesh({0, 0.2f, 1}, {0, 0.2f, 1}, {0, 0.2f, 1}), white, 1e6f, "point light");
  Rendered r = render_checked(b.finish(camera_looking_z(0, 0, 0, 60, 16)), 102, 16);
  EXPECT_EQ(r.nonfinite, 0u);
  for (float v : r.rgb) ASSERT_EQ(v, 0.0f);
}

// Slivers: vertices 1e-6 relative apart (area ~1e-7) and 1e-20 apart (the cross product
// underflows in float), also as emitters. Their area is far below what the statistical
// tolerance can see, so the furnace radiance is unchanged.
TEST(FurnaceObjects, NearlyCoincidentVerticesStayFinite) {
  SceneBuilder b(furnace_scene(kAlbedo, kLe, kRes));
  int grey = b.material(diffuse_material(0.9f), "grey");
  b.shape(triangle_mesh({0, 0, 0.5f}, {1e-6f, 0, 0.5f}, {0, 1e-6f, 0.5f}), grey, 0.0f, "tiny");
  b.shape(triangle_mesh({-0.5f, 0, 0.5f}, {0.5f, 1e-7f, 0.5f}, {0.5f, 0, 0.5f}), grey, 100.0f, "sliver light");
  b.shape(triangle_mesh({0.1f, 0.1f, 0.4f}, {0.1f + 1e-20f, 0.1f, 0.4f}, {0.1f, 0.1f + 1e-20f, 0.4f}), grey, 1e6f,
          "underflow light");
  b.shape(triangle_mesh({-0.2f, 0.3f, 0.5f}, {0.2f, 0.3f, 0.5f}, {0.2f, 0.3f, 0.5f + 1e-6f}), grey, 0.0f,
          "needle");
  expect_furnace_radiance(b.finish(furnace_scene(kAlbedo, kLe, kRes).camera), 103, "slivers");
}

// Smooth and thin dielectrics with eta = 1 neither reflect nor bend light.
TEST(FurnaceObjects, IndexMatchedGlassSphereIsInvisible) {
  for (int type : {BSDF_DIELECTRIC, BSDF_THIN_DIELECTRIC}) {
    SceneBuilder b(furnace_scene(kAlbedo, kLe, kRes));
    int glass = b.material(dielectric_material(type, 1.0f), "index-matched");
    b.shape(sphere_mesh({0.1f, -0.1f, 0.5f}, 0.35f), glass, 0.0f, "sphere");
    expect_furnace_radiance(b.finish(furnace_scene(kAlbedo, kLe, kRes).camera), 104 + type,
                            type == BSDF_DIELECTRIC ? "dielectric eta 1" : "thin dielectric eta 1");
  }
}

// A glass box (eta 1.5): light refracted in through one face meets the adjacent faces beyond the
// critical angle (41.8 degrees) and is reflected totally, so paths bounce inside many times. A
// lossless dielectric leaves a uniform radiance field unchanged.
TEST(FurnaceObjects, GlassBoxWithTotalInternalReflectionIsInvisible) {
  SceneBuilder b(furnace_scene(kAlbedo, kLe, kRes));
  int glass = b.material(dielectric_material(BSDF_DIELECTRIC, 1.5f), "glass");
  b.shape(box_mesh({-0.4f, -0.3f, 0.3f}, {0.5f, 0.1f, 0.7f}), glass, 0.0f, "slab");
  expect_furnace_radiance(b.finish(furnace_scene(kAlbedo, kLe, kRes).camera), 110, "glass box");
}

// The camera inside a glass slab sees the field scaled by eta^2 (radiance is eta^2 L in a medium
// of index eta), much of it through total internal reflection (critical angle 56.4 degrees at
// eta 1.2). In a box a direction keeps |x|, |y|, |z| through reflections, and it is trapped for
// ever when all three are below sqrt(1 - 1 / eta^2); for eta^2 < 3/2 no unit direction is, so
// every path leaves (at eta 1.5 some never do, and the camera rightly sees them black).
TEST(FurnaceObjects, InsideGlassSlabRadianceScalesWithEtaSquared) {
  const float eta = 1.2f;
  Scene base = furnace_scene(kAlbedo, kLe, kRes);
  SceneBuilder b(base);
  int glass = b.material(dielectric_material(BSDF_DIELECTRIC, eta), "glass");
  b.shape(box_mesh({-0.8f, -0.5f, -0.5f}, {0.8f, 0.1f, 0.5f}), glass, 0.0f, "slab");
  Rendered r = render_checked(b.finish(base.camera), 111, kSpp);
  ASSERT_TRUE(all_finite(r.rgb));
  EXPECT_EQ(r.nonfinite, 0u);
  const double expected = eta * eta * kLe / (1.0 - kAlbedo);
  double mean = 0, se = 0;
  double z = mean_z(r.rgb, std::vector<double>(r.rgb.size(), expected), &mean, &se);
  EXPECT_LT(std::fabs(z), 5.0) << "mean " << expected + mean << " expected " << expected << " se " << se;
}

// A perfect mirror (reflectance 1) is invisible in the furnace: as a smooth conductor and as
// rough conductors at alpha 1e-4 (GGX and Beckmann), whose energy loss at that roughness is far
// below the tolerance.
TEST(FurnaceObjects, NearDeltaMirrorSphereIsInvisible) {
  std::vector<GdrMaterial> mirrors = {mirror_material(BSDF_CONDUCTOR)};
  for (int d : {MICROFACET_GGX, MICROFACET_BECKMANN}) {
    GdrMaterial m = mirror_material(BSDF_ROUGH_CONDUCTOR);
    m.distribution = d;
    m.alpha_u = m.alpha_v = 1e-4f;
    mirrors.push_back(m);
  }
  uint32_t seed = 120;
  for (const GdrMaterial& m : mirrors) {
    SceneBuilder b(furnace_scene(kAlbedo, kLe, kRes));
    int mirror = b.material(m, "mirror");
    b.shape(sphere_mesh({0.0f, 0.0f, 0.5f}, 0.35f), mirror, 0.0f, "sphere");
    std::string what = "mirror type " + std::to_string(m.type) + " distribution " + std::to_string(m.distribution);
    expect_furnace_radiance(b.finish(furnace_scene(kAlbedo, kLe, kRes).camera), seed++, what.c_str());
  }
}

}  // namespace
}  // namespace gdr::test
