// G-PT and PT at the image's edges, where the pixel filter is cut to the image (the film's
// sample_border is false by default) and G-PT's pixel shift must carry the ratio of the two
// pixels' film densities. A diffuse plane (albedo 0.5) fills the view under a constant sky of
// radiance 1, so every pixel, also on the border, is exactly 0.5 for any filter, and every
// gradient is 0. One render of each (seed 5, 32 x 32 pixels, 512 spp, one bounce); for each
// border row and column (and the gradients touching it), a one-sample t-test over its 32
// pixel estimates against the exact value at |t| < 5.5 (df 31; 12 tests, family-wise false-
// positive rate < 1e-4). Without the density ratio the border pixels are off by about 2%.
#include <gtest/gtest.h>

#include <cmath>

#include "integrators/gpt/gradient_path_tracer.h"
#include "scene/scene_test_files.h"
#include "support/render.h"

namespace gdr {
namespace {

constexpr int kBorderSize = 32, kBorderSpp = 512;
constexpr double kAlbedo = 0.5;

const char* kScene = R"(
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="32"/></film>
  </sensor>
  <shape type="rectangle"><transform name="to_world"><scale value="100"/></transform>
    <bsdf type="diffuse"><rgb name="reflectance" value="0.5"/></bsdf></shape>
  <emitter type="constant"><rgb name="radiance" value="1"/></emitter>)";

// Luminance of pixels (x0 + i dx, y0 + i dy), i < kBorderSize, and the t statistic of their mean
// against `expected`.
double t_statistic(const std::vector<float>& rgb, int x0, int y0, int dx, int dy, double expected,
                   int count = kBorderSize) {
  double sum = 0, sum2 = 0;
  for (int i = 0; i < count; ++i) {
    const float* c = &rgb[3 * size_t((y0 + i * dy) * kBorderSize + x0 + i * dx)];
    double v = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    sum += v;
    sum2 += v * v;
  }
  double mean = sum / count, var = (sum2 - count * mean * mean) / (count - 1);
  return (mean - expected) / std::sqrt(std::max(var, 1e-30) / count);
}

TEST(GptBorder, PrimalAndGradientsAtTheEdgesMatchTheExactImage) {
  test::TempFolder folder;
  Scene scene = load_scene(folder.write("scene.xml", test::scene_xml(kScene)));
  ASSERT_EQ(scene.camera.sample_border, 0);
  test::SceneOnDevice on_device(scene);
  RenderSettings s;
  s.spp = kBorderSpp;
  s.seed = 5;
  s.max_depth = 2;
  GradientPathTracer gpt(on_device.inputs(), GptSettings{});
  GradientImages g = gpt.render_gradients(s);
  PathTracer pt(on_device.inputs(), PtSettings{});
  std::vector<float> img = pt.render(s).image.rgb_layer("");
  const int last = kBorderSize - 1;
  struct Line {
    const char* name;
    int x0, y0, dx, dy;
  };
  const Line edges[] = {{"left column", 0, 0, 0, 1}, {"right column", last, 0, 0, 1},
                        {"top row", 0, 0, 1, 0}, {"bottom row", 0, last, 1, 0}};
  for (const Line& e : edges) {
    EXPECT_LT(std::fabs(t_statistic(g.primal, e.x0, e.y0, e.dx, e.dy, kAlbedo)), 5.5) << "gpt primal, " << e.name;
    EXPECT_LT(std::fabs(t_statistic(img, e.x0, e.y0, e.dx, e.dy, kAlbedo)), 5.5) << "pt, " << e.name;
  }
  // dx between the first two and the last two columns; dy between the first two and last two rows
  // (the last row and column hold no forward difference).
  EXPECT_LT(std::fabs(t_statistic(g.dx, 0, 0, 0, 1, 0.0)), 5.5) << "dx, left edge";
  EXPECT_LT(std::fabs(t_statistic(g.dx, last - 1, 0, 0, 1, 0.0)), 5.5) << "dx, right edge";
  EXPECT_LT(std::fabs(t_statistic(g.dy, 0, 0, 1, 0, 0.0, last)), 5.5) << "dy, top edge";
  EXPECT_LT(std::fabs(t_statistic(g.dy, 0, last - 1, 1, 0, 0.0, last)), 5.5) << "dy, bottom edge";
}

}  // namespace
}  // namespace gdr
