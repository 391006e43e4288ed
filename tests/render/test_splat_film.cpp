// The splat film (engine/render/splat_film.h): slots add their value times each pixel's
// normalized filter into the film, empty slots add nothing, the slots are emptied by a gather,
// the image is the same bit for bit from gather to gather, and a slot's value is spread with
// weights that sum to about one.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "render/splat_film.h"
#include "support/devices.h"
#include "support/test_scenes.h"

namespace gdr {
namespace {

constexpr const char* kProgram = "tests/splat_test.cl";

// n slots at film positions uniform over a w x h film (std::mt19937 seed 29), values in
// [0, 1)^3, every fifth slot empty.
std::vector<GdrSplat> random_slots(size_t n, int w, int h) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<GdrSplat> s(n);
  for (size_t i = 0; i < n; ++i) {
    s[i].raster[0] = u(rng) * w;
    s[i].raster[1] = u(rng) * h;
    for (float& v : s[i].value) v = u(rng);
    s[i].valid = i % 5 != 4;
  }
  return s;
}

struct SplatSetup {
  explicit SplatSetup(int filter, float radius)
      : scene(test::furnace_scene(0.5f, 1.0f, 8)), kernels(test::default_context(), scene) {
    cam = test::camera_looking_z(0, 0, 0, 40.0f, 24);
    cam.height = 17;
    cam.filter = filter;
    cam.filter_radius = radius;
  }
  // The film after gathering `slots`.
  std::vector<Vec4> gather(const std::vector<GdrSplat>& slots) {
    Context& ctx = test::default_context();
    SplatFilm splats(ctx, kernels, kProgram, slots.size());
    splats.slots().write(slots);
    Buffer<GdrCamera> camera(ctx, std::vector<GdrCamera>{cam});
    Buffer<Vec4> film(ctx, size_t(cam.width) * cam.height);
    film.fill(Vec4{});
    splats.gather(camera, cam.height, cl_uint(slots.size()), film);
    std::vector<Vec4> first = film.read();
    // The slots are empty now: a second gather adds nothing.
    splats.gather(camera, cam.height, cl_uint(slots.size()), film);
    std::vector<Vec4> second = film.read();
    EXPECT_EQ(0, std::memcmp(first.data(), second.data(), first.size() * sizeof(Vec4)))
        << "a gather did not empty the slots";
    return first;
  }
  Scene scene;
  KernelFactory kernels;
  GdrCamera cam;
};

// With the box filter of radius 1/2 a slot lands on the one pixel holding it with weight 1: the
// film is the sum of the full slots' values per pixel, added in slot order (bit for bit).
TEST(SplatFilm, BoxFilterAddsEachSlotToItsPixelInSlotOrder) {
  SplatSetup setup(FILTER_BOX, 0.5f);
  std::vector<GdrSplat> slots = random_slots(5000, setup.cam.width, setup.cam.height);
  std::vector<Vec4> got = setup.gather(slots);
  std::vector<float> expected(size_t(setup.cam.width) * setup.cam.height * 3, 0.0f);
  for (const GdrSplat& s : slots) {
    if (!s.valid) continue;
    int x = std::min(int(s.raster[0]), setup.cam.width - 1), y = std::min(int(s.raster[1]), setup.cam.height - 1);
    for (int c = 0; c < 3; ++c) expected[3 * (y * setup.cam.width + x) + c] += s.value[c];
  }
  for (size_t p = 0; p < got.size(); ++p) {
    EXPECT_EQ(got[p].x, expected[3 * p]) << "pixel " << p;
    EXPECT_EQ(got[p].y, expected[3 * p + 1]) << "pixel " << p;
    EXPECT_EQ(got[p].z, expected[3 * p + 2]) << "pixel " << p;
  }
}

// The gaussian filter spreads each slot over up to 5 x 5 pixels, gathered by different rows' work
// items: two gathers of the same slots give the same image bit for bit, and each slot's value is
// spread with weights summing to about 1 (the gaussian's normalized weights are close to a
// partition of unity away from the edges).
TEST(SplatFilm, GaussianImageIsDeterministicAndKeepsTheTotal) {
  SplatSetup setup(FILTER_GAUSSIAN, 2.0f);
  std::vector<GdrSplat> slots = random_slots(20000, setup.cam.width, setup.cam.height);
  std::vector<Vec4> ref = setup.gather(slots), again = setup.gather(slots);
  EXPECT_EQ(0, std::memcmp(ref.data(), again.data(), ref.size() * sizeof(Vec4)));
  double total = 0, in = 0;
  for (const Vec4& v : ref) total += v.x;
  for (const GdrSplat& s : slots) in += s.valid ? s.value[0] : 0.0;
  EXPECT_NEAR(total / in, 1.0, 0.02);
}

}  // namespace
}  // namespace gdr
