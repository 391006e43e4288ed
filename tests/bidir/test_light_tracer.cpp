// The light tracer (`lt`) converges to the path tracer's image: per 4 x 4 pixel block, Welch's
// t-test compares the mean luminance of K independent runs of each (seeds 1..K for lt, 101..100+K
// for pt), Šidák-corrected over the blocks of a scene so that each scene's test has a
// false-positive rate of 1e-3. Emission seen directly comes from camera rays, light subpaths add
// the rest; the image is the same for the same seed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "integrators/bidir/light_tracer.h"
#include "scene/load_scene.h"
#include "support/render.h"
#include "support/statistics.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

constexpr int kBlock = 4, kRuns = 16;

// runs[k][block]: the block's mean luminance in run k of `integrator`.
std::vector<std::vector<double>> block_means(Integrator& integrator, int width, int height, int spp, int max_depth,
                                             uint32_t first_seed) {
  std::vector<std::vector<double>> runs;
  for (int k = 0; k < kRuns; ++k) {
    RenderSettings s;
    s.spp = spp;
    s.seed = first_seed + k;
    s.max_depth = max_depth;
    std::vector<float> rgb = integrator.render(s).image.rgb_layer("");
    std::vector<double> blocks((width / kBlock) * (height / kBlock), 0.0);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float* c = &rgb[3 * (y * width + x)];
        blocks[(y / kBlock) * (width / kBlock) + x / kBlock] += 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
      }
    runs.push_back(blocks);
  }
  return runs;
}

// A small film of the scene's aspect (the field of view unchanged), whole blocks only.
Scene small_film(Scene scene, int width) {
  int height = std::max(kBlock, (width * scene.camera.height / scene.camera.width) / kBlock * kBlock);
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

void expect_agrees_with_pt(const Scene& scene, const std::string& name, int lt_spp, int pt_spp, int max_depth) {
  test::SceneOnDevice on_device(scene);
  LightTracer lt(on_device.inputs(), LtSettings{});
  PathTracer pt(on_device.inputs(), PtSettings{});
  const int w = scene.camera.width, h = scene.camera.height;
  auto a = block_means(lt, w, h, lt_spp, max_depth, 1);
  auto b = block_means(pt, w, h, pt_spp, max_depth, 101);
  const int blocks = int(a[0].size());
  const double alpha = test::sidak(1e-3, blocks);
  int lit = 0;
  for (int i = 0; i < blocks; ++i) {
    std::vector<double> x, y;
    for (int k = 0; k < kRuns; ++k) {
      x.push_back(a[k][i]);
      y.push_back(b[k][i]);
    }
    lit += test::mean_and_variance(y).mean > 0;
    EXPECT_GT(test::welch_p(x, y), alpha) << name << " block " << i << ": lt " << test::mean_and_variance(x).mean
                                          << ", pt " << test::mean_and_variance(y).mean;
  }
  EXPECT_GT(lit, blocks / 2) << name << ": too few lit blocks to show anything";
}

TEST(LightTracer, CornellBoxAgreesWithPt) {
  Scene scene = small_film(load_scene(std::string(GDR_SOURCE_DIR) + "/scenes/cornell-box.xml"), 24);
  expect_agrees_with_pt(scene, "cornell-box.xml", 16, 16, 6);
}

// Glossy plates under small spherical lights; the plates are made at least 0.2 rough, as the
// path tracer's strategy test does for its light-only technique (a light subpath reaches the
// camera from a smoother plate too rarely for a t-test over a few runs to be valid).
TEST(LightTracer, GlossyPlatesAgreeWithPt) {
  Scene scene = load_scene(std::string(GDR_SOURCE_DIR) + "/scenes/glossy-plates.xml");
  for (GdrMaterial& m : scene.materials) {
    if (m.type == BSDF_ROUGH_PLASTIC) m.alpha_u = m.alpha_v = std::max(m.alpha_u, 0.2f);
  }
  expect_agrees_with_pt(small_film(scene, 32), "glossy-plates.xml (plates at least 0.2 rough)", 16, 16, 6);
}

// A coarse diffuse sphere (4 x 8 facets) with smooth vertex normals on a floor before a wall,
// under a small area light: its shading normals differ from its facets' by up to ~40 degrees,
// where importance transport needs the shading-normal correction to give pt's image.
TEST(LightTracer, ShadingNormalsAgreeWithPt) {
  test::SceneBuilder b;
  GdrMaterial m{};
  m.type = BSDF_DIFFUSE;
  m.reflectance_texture = -1;
  m.coating_table = -1;
  m.reflectance[0] = m.reflectance[1] = m.reflectance[2] = 0.7f;
  int white = b.material(m, "white");
  MeshData sphere = make_sphere(4, 8);
  for (size_t v = 0; v < sphere.vertex_count(); ++v) sphere.positions[3 * v + 2] += 3.0f;
  b.shape(sphere, white, 0.0f, "sphere");
  b.shape(test::quad_mesh({-3, -1, 0}, {-3, -1, 6}, {3, -1, 6}, {3, -1, 0}), white, 0.0f, "floor");
  b.shape(test::quad_mesh({-3, -1, 6}, {-3, 3, 6}, {3, 3, 6}, {3, -1, 6}), white, 0.0f, "wall");
  b.shape(test::quad_mesh({-0.75f, 2.5f, 2.25f}, {0.75f, 2.5f, 2.25f}, {0.75f, 2.5f, 3.75f}, {-0.75f, 2.5f, 3.75f}),
          white, 5.0f, "light");
  Scene scene = b.finish(test::camera_looking_z(0.0f, 0.3f, 0.5f, 45.0f, 24));
  ASSERT_TRUE(scene.shapes[0].flags & SHAPE_HAS_NORMALS);
  expect_agrees_with_pt(scene, "coarse smooth sphere", 64, 64, 4);
}

// max_depth 1 is the emission seen directly: the camera rays' part alone, which is exactly what
// pt's camera rays see (same pixel sampler, same seed: the same image bit for bit).
TEST(LightTracer, DirectlyVisibleEmissionIsPtsFirstSegment) {
  Scene scene = small_film(load_scene(std::string(GDR_SOURCE_DIR) + "/scenes/cornell-box.xml"), 32);
  test::SceneOnDevice on_device(scene);
  LightTracer lt(on_device.inputs(), LtSettings{});
  PathTracer pt(on_device.inputs(), PtSettings{});
  RenderSettings s;
  s.spp = 4;
  s.seed = 3;
  s.max_depth = 1;
  std::vector<float> a = lt.render(s).image.rgb_layer(""), b = pt.render(s).image.rgb_layer("");
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float)));
  EXPECT_GT(*std::max_element(a.begin(), a.end()), 0.0f) << "the light is not in view";
  // max_depth 0 renders nothing.
  s.max_depth = 0;
  std::vector<float> none = lt.render(s).image.rgb_layer("");
  EXPECT_EQ(*std::max_element(none.begin(), none.end()), 0.0f);
}

// Same seed, same image (splats gathered in slot order), different seed, different image.
TEST(LightTracer, SameSeedSameImage) {
  Scene scene = small_film(load_scene(std::string(GDR_SOURCE_DIR) + "/scenes/cornell-box.xml"), 32);
  test::SceneOnDevice on_device(scene);
  LightTracer lt(on_device.inputs(), LtSettings{});
  RenderSettings s;
  s.spp = 2;
  s.seed = 9;
  std::vector<float> a = lt.render(s).image.rgb_layer(""), b = lt.render(s).image.rgb_layer("");
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float)));
  s.seed = 10;
  std::vector<float> c = lt.render(s).image.rgb_layer("");
  EXPECT_NE(0, std::memcmp(a.data(), c.data(), a.size() * sizeof(float)));
}

// The white furnace: inside a closed diffuse cube of albedo a whose walls emit le, every pixel
// sees le / (1 - a); light subpaths of every length add up to it (unbounded depth, Russian
// roulette), and every pixel is finite.
TEST(LightTracer, WhiteFurnace) {
  Scene scene = test::furnace_scene(0.5f, 1.0f, 8);
  test::SceneOnDevice on_device(scene);
  LightTracer lt(on_device.inputs(), LtSettings{});
  RenderSettings s;
  s.spp = 256;
  s.seed = 4;
  s.max_depth = -1;
  std::vector<float> rgb = lt.render(s).image.rgb_layer("");
  double sum = 0, sum2 = 0;
  for (float v : rgb) {
    ASSERT_TRUE(std::isfinite(v));
    sum += v;
    sum2 += double(v) * v;
  }
  // The standard error of the image mean from the spread of its 64 x 3 values (each pixel's
  // splats come from different vertices); 5 standard errors: false-positive rate below 1e-6.
  double n = double(rgb.size()), mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, 2.0, 5 * se) << "standard error " << se;
  EXPECT_LT(se, 0.02);
  EXPECT_GT(se, 0.0);  // a noise-free image would mean nothing was sampled
}

}  // namespace
}  // namespace gdr
