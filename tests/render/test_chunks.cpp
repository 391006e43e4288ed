// How a render's pixels are split into chunks (paths in flight at once: smaller on a CPU device,
// device_chunk_capacity) does not change the image of an integrator whose chunks do not share
// photons: the caustics box (mirror, glass, diffuse) at 160 x 160, 25600 pixels, 2 spp, seed 5,
// rendered as one chunk and as six (5000 pixels a chunk, the last 600). gpt's layers are the
// same bit for bit; bdpt and gbdpt splat light tracing's contributions from every chunk onto
// the same pixels, which sums them in another order, so their images agree to float rounding
// (1e-5 of the image's largest value). The default on this (CPU) device splits the film into two chunks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "integrators/bidir/bidirectional.h"
#include "integrators/gbidir/gradient_bidirectional.h"
#include "integrators/gpt/gradient_path_tracer.h"
#include "render/wavefront/chunks.h"
#include "support/agreement.h"
#include "support/render.h"

namespace gdr {
namespace {

constexpr size_t kChunk = 5000;

Scene chunked_scene() { return test::project_scene("cornell-box-caustics.xml", 160); }

RenderSettings settings() {
  RenderSettings s;
  s.spp = 2;
  s.seed = 5;
  return s;
}

// The largest difference of a and b over the largest value of `image` (a caustic's pixel, far
// above the mean, carries rounding differences in proportion).
double largest_difference(const std::vector<float>& a, const std::vector<float>& b, const std::vector<float>& image) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0, largest = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, std::fabs(double(a[i]) - double(b[i])));
  for (float v : image) largest = std::max(largest, double(std::fabs(v)));
  EXPECT_GT(largest, 0.0);
  return worst / largest;
}

TEST(Chunks, CpuDeviceSplitsLargeFilms) {
  const Scene scene = chunked_scene();
  const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
  EXPECT_EQ(device_chunk_capacity(size_t(1) << 17, true, 0, scene.camera.width, scene.camera.height),
            kCpuMaxInFlight);
  EXPECT_LT(kCpuMaxInFlight, pixels);
  EXPECT_EQ(device_chunk_capacity(size_t(1) << 17, false, 0, scene.camera.width, scene.camera.height), pixels);
  EXPECT_EQ(device_chunk_capacity(size_t(1) << 17, true, kChunk, scene.camera.width, scene.camera.height), kChunk);
}

TEST(Chunks, GptImagesDoNotDependOnTheChunks) {
  const Scene scene = chunked_scene();
  test::SceneOnDevice on_device(scene);
  const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
  GradientImages gpt[2];
  for (int k = 0; k < 2; ++k) {
    GptSettings gs;
    gs.in_flight = k == 0 ? pixels : kChunk;
    gpt[k] = GradientPathTracer(on_device.inputs(), gs).render_gradients(settings());
  }
  EXPECT_GT(*std::max_element(gpt[0].dx.begin(), gpt[0].dx.end()), 0.0f);
  EXPECT_EQ(gpt[0].primal, gpt[1].primal);
  EXPECT_EQ(gpt[0].dx, gpt[1].dx);
  EXPECT_EQ(gpt[0].dy, gpt[1].dy);
  EXPECT_EQ(gpt[0].direct, gpt[1].direct);
}

TEST(Chunks, BdptAndGbdptImagesDoNotDependOnTheChunks) {
  const Scene scene = chunked_scene();
  test::SceneOnDevice on_device(scene);
  const size_t pixels = size_t(scene.camera.width) * size_t(scene.camera.height);
  std::vector<float> bdpt[2];
  GradientImages gbdpt[2];
  for (int k = 0; k < 2; ++k) {
    BidirSettings bs = bdpt_settings(IntegratorParams{});
    bs.in_flight = k == 0 ? pixels : kChunk;
    bdpt[k] = Bidirectional(on_device.inputs(), bs).render(settings()).image.rgb_layer("");
    GptSettings gs = gbdpt_settings(IntegratorParams{});
    gs.in_flight = k == 0 ? pixels : kChunk;
    gbdpt[k] = GradientBidirectional(on_device.inputs(), gs).render_gradients(settings());
  }
  EXPECT_LT(largest_difference(bdpt[0], bdpt[1], bdpt[0]), 1e-5);
  EXPECT_LT(largest_difference(gbdpt[0].primal, gbdpt[1].primal, gbdpt[0].primal), 1e-5);
  EXPECT_LT(largest_difference(gbdpt[0].dx, gbdpt[1].dx, gbdpt[0].primal), 1e-5);
  EXPECT_LT(largest_difference(gbdpt[0].dy, gbdpt[1].dy, gbdpt[0].primal), 1e-5);
}

}  // namespace
}  // namespace gdr
