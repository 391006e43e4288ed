// The scene-buffer list (kernels/shared/scene_buffers.h) binds as the kernels declare it: a
// kernel reading each buffer through SCENE_DATA_ARGS, with DeviceScene passed among its other
// arguments, sees every word of the host's arrays, buffer by buffer. A scene with an
// environment map, spheres (normals, uvs) and its materials, the ground made rough plastic (a
// coating table), so that no buffer is empty.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "render/device_scene.h"
#include "shared/environment_table.h"
#include "support/devices.h"
#include "support/envmap_scene.h"

namespace gdr {
namespace {

struct Words {
  std::vector<std::string> names;
  std::vector<cl_uint> offsets{0};
  std::vector<cl_uint> words;
};

// The host arrays' words, in list order.
Words host_words(const SceneArrays& a) {
  Words w;
#define GDR_HOST_WORDS(ktype, htype, name, what)                                  \
  {                                                                               \
    size_t n = a.name.size() * sizeof(htype) / 4;                                 \
    size_t at = w.words.size();                                                   \
    w.words.resize(at + n);                                                       \
    if (n) std::memcpy(&w.words[at], a.name.data(), n * 4);                       \
    w.names.push_back(#name);                                                     \
    w.offsets.push_back(cl_uint(w.words.size()));                                 \
  }
  GDR_SCENE_BUFFERS(GDR_HOST_WORDS, GDR_HOST_WORDS)
#undef GDR_HOST_WORDS
  return w;
}

// The envmap scene with its last shape (the ground) made rough plastic.
Scene scene_with_plastic() {
  Scene scene = test::envmap_scene();
  GdrMaterial plastic = scene.materials[scene.shapes.back().material];
  plastic.type = BSDF_ROUGH_PLASTIC;
  plastic.eta[0] = 1.5f;
  plastic.alpha_u = plastic.alpha_v = 0.2f;
  scene.shapes.back().material = static_cast<int>(scene.materials.size());
  scene.materials.push_back(plastic);
  scene.material_names.push_back("rough plastic ground");
  return scene;
}

TEST(SceneBuffers, KernelSeesEveryBufferAsUploaded) {
  Scene scene = scene_with_plastic();
  Context& ctx = test::default_context();
  SceneArrays arrays = scene_arrays(ctx, scene);
  Words host = host_words(arrays);
  for (size_t b = 0; b < host.names.size(); ++b) {
    ASSERT_GT(host.offsets[b + 1], host.offsets[b]) << "the test scene has no " << host.names[b];
  }
  DeviceScene device(ctx, scene);
  Buffer<cl_uint> offsets(ctx, host.offsets);
  Buffer<cl_uint> out(ctx, host.words.size());
  out.fill(0xDEADBEEFu);
  ctx.program("tests/scene_buffers_test.cl")
      ->kernel("scene_buffers_copy")
      .args(device, offsets, out)
      .run(host.words.size());
  std::vector<cl_uint> seen = out.read();
  for (size_t b = 0; b < host.names.size(); ++b) {
    size_t wrong = 0;
    for (cl_uint i = host.offsets[b]; i < host.offsets[b + 1]; ++i) wrong += seen[i] != host.words[i];
    EXPECT_EQ(wrong, 0u) << host.names[b] << ": " << wrong << " of " << host.offsets[b + 1] - host.offsets[b]
                         << " words differ";
  }
}

// The environment tables follow their shared layout: the row sums are those of the rows'
// weights (the fourth channel of the map's texels, whose radiance stays), and the bilinear
// interpolant of the weights integrates to 1 over the grid (each band between rows the mean of
// its two rows' sums).
TEST(SceneBuffers, EnvironmentTablesFollowTheSharedLayout) {
  Scene scene = test::envmap_scene();
  SceneArrays a = scene_arrays(test::default_context(), scene);
  const GdrLight& env = a.lights.back();
  ASSERT_EQ(env.type, LIGHT_ENVMAP);
  const GdrTexture& t = a.textures[env.texture];
  const int w = t.width, h = t.height;
  ASSERT_EQ(a.env_tables.size(), size_t(env.distribution_offset + env_table_size(w, h)));
  const float* table = &a.env_tables[env.distribution_offset];
  const float* sums = table + env_table_row_sums_offset(h);
  ASSERT_LE(sums + h, table + env_table_aliases_offset(w, h, 0));
  double integral = 0;
  for (int r = 0; r < h; ++r) {
    const Vec4* f = &a.texels[size_t(t.offset) + size_t(r) * w];
    double sum = 0;
    for (int c = 0; c < w; ++c) {
      EXPECT_GE(f[c].w, 0.0f);
      EXPECT_EQ(f[c].x, scene.texels[size_t(t.offset) + size_t(r) * w + c].x);  // the radiance kept
      sum += f[c].w;
    }
    EXPECT_NEAR(sums[r], sum, 1e-5) << "row " << r;
    if (r + 1 < h) integral += 0.5 * sums[r];
    if (r > 0) integral += 0.5 * sums[r];
  }
  EXPECT_NEAR(integral, 1.0, 1e-5);
}

// Each alias table draws every interval with its share of the masses: bucket j keeps j with its
// stored probability and hands the rest to its alias, so interval j's probability is
// (keep_j + the sum of 1 - keep_i over buckets i aliased to j) / n. Checked for the bands (masses:
// the mean of their rows' sums) and every row's intervals (the mean of the weights at their ends).
TEST(SceneBuffers, EnvironmentAliasTablesDrawEachIntervalByItsMass) {
  Scene scene = test::envmap_scene();
  SceneArrays a = scene_arrays(test::default_context(), scene);
  const GdrLight& env = a.lights.back();
  const GdrTexture& t = a.textures[env.texture];
  const int w = t.width, h = t.height;
  const float* table = &a.env_tables[env.distribution_offset];
  auto check = [](const float* alias, const std::vector<double>& mass, const std::string& what) {
    const int n = static_cast<int>(mass.size());
    double total = 0;
    for (double m : mass) total += m;
    ASSERT_GT(total, 0.0) << what;
    std::vector<double> p(n, 0.0);
    for (int i = 0; i < n; ++i) {
      const float keep = alias[2 * i], other = alias[2 * i + 1];
      ASSERT_GE(keep, 0.0f) << what << " bucket " << i;
      ASSERT_LE(keep, 1.0f) << what << " bucket " << i;
      ASSERT_EQ(other, std::floor(other)) << what << " bucket " << i;
      ASSERT_GE(other, 0.0f) << what << " bucket " << i;
      ASSERT_LT(other, static_cast<float>(n)) << what << " bucket " << i;
      p[i] += keep / n;
      p[static_cast<int>(other)] += (1.0 - keep) / n;
    }
    for (int j = 0; j < n; ++j) EXPECT_NEAR(p[j], mass[j] / total, 1e-6) << what << " interval " << j;
  };
  const float* sums = table + env_table_row_sums_offset(h);
  std::vector<double> bands(h - 1);
  for (int b = 0; b + 1 < h; ++b) bands[b] = 0.5 * (double(sums[b]) + sums[b + 1]);
  check(table, bands, "bands");
  for (int r = 0; r < h; ++r) {
    const Vec4* f = &a.texels[size_t(t.offset) + size_t(r) * w];
    std::vector<double> intervals(w);
    for (int c = 0; c < w; ++c) intervals[c] = 0.5 * (double(f[c].w) + f[(c + 1) % w].w);
    check(table + env_table_aliases_offset(w, h, r), intervals, "row " + std::to_string(r));
  }
}

}  // namespace
}  // namespace gdr
