// The scene-buffer list (kernels/shared/scene_buffers.h) binds as the kernels declare it: a
// kernel reading each buffer through SCENE_DATA_ARGS, with DeviceScene passed among its other
// arguments, sees every word of the host's arrays, buffer by buffer. A scene with an
// environment map, spheres (normals, uvs) and its materials, the ground made rough plastic (a
// coating table), so that no buffer is empty.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

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

// The environment tables follow their shared layout: each cdf starts at 0 and ends at 1, the
// row sums are those of the rows' weights, and the bilinear interpolant of the weights
// integrates to 1 over the grid (each band between rows the mean of its two rows' sums).
TEST(SceneBuffers, EnvironmentTablesFollowTheSharedLayout) {
  Scene scene = test::envmap_scene();
  SceneArrays a = scene_arrays(test::default_context(), scene);
  const GdrLight& env = a.lights.back();
  ASSERT_EQ(env.type, LIGHT_ENVMAP);
  const GdrTexture& t = a.textures[env.texture];
  const int w = t.width, h = t.height;
  ASSERT_EQ(a.env_tables.size(), size_t(env.distribution_offset + env_table_size(w, h)));
  const float* table = &a.env_tables[env.distribution_offset];
  EXPECT_EQ(table[0], 0.0f);
  EXPECT_EQ(table[h - 1], 1.0f);
  const float* sums = table + env_table_row_sums_offset(h);
  double integral = 0;
  for (int r = 0; r < h; ++r) {
    const float* cols = table + env_table_columns_offset(w, h, r);
    EXPECT_EQ(cols[0], 0.0f) << "row " << r;
    EXPECT_EQ(cols[w], 1.0f) << "row " << r;
    const float* f = table + env_table_weights_offset(w, h, r);
    double sum = 0;
    for (int c = 0; c < w; ++c) {
      EXPECT_GE(f[c], 0.0f);
      sum += f[c];
    }
    EXPECT_NEAR(sums[r], sum, 1e-5) << "row " << r;
    if (r + 1 < h) integral += 0.5 * sums[r];
    if (r > 0) integral += 0.5 * sums[r];
  }
  EXPECT_NEAR(integral, 1.0, 1e-5);
}

// Each guide entry j is the interval u = j / K falls in, so every u of bucket j falls between
// entries j and j + 1: the guided search finds the interval a search of the whole cdf finds.
// Checked for the band cdf and every row's, at the bucket's ends and 16 points inside each bucket.
TEST(SceneBuffers, EnvironmentGuidesBoundEachBucketsInterval) {
  Scene scene = test::envmap_scene();
  SceneArrays a = scene_arrays(test::default_context(), scene);
  const GdrLight& env = a.lights.back();
  const GdrTexture& t = a.textures[env.texture];
  const int w = t.width, h = t.height;
  const float* table = &a.env_tables[env.distribution_offset];
  auto check = [](const float* cdf, const float* guide, int n, const std::string& what) {
    auto interval = [&](float u) {
      return static_cast<int>(std::upper_bound(cdf + 1, cdf + n, u) - (cdf + 1));
    };
    const int k = env_table_guide_buckets(n);
    ASSERT_GE(k, n);
    ASSERT_LT(k, 2 * std::max(n, 1));
    for (int j = 0; j < k; ++j) {
      const float lo = static_cast<float>(j) / k, hi = static_cast<float>(j + 1) / k;
      ASSERT_EQ(guide[j], static_cast<float>(interval(lo))) << what << " bucket " << j;
      for (int m = 0; m <= 16; ++m) {
        const float u = std::nextafter(lo + (hi - lo) * (m / 16.0f), m == 16 ? 0.0f : 2.0f);
        const int i = interval(u);
        ASSERT_LE(guide[j], static_cast<float>(i)) << what << " bucket " << j << " u " << u;
        ASSERT_GE(guide[j + 1], static_cast<float>(i)) << what << " bucket " << j << " u " << u;
      }
    }
  };
  check(table, table + env_table_band_guide_offset(w, h), h - 1, "bands");
  for (int r = 0; r < h; ++r) {
    check(table + env_table_columns_offset(w, h, r), table + env_table_column_guide_offset(w, h, r), w,
          "row " + std::to_string(r));
  }
}

}  // namespace
}  // namespace gdr
