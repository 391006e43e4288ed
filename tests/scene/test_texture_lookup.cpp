// Texture lookups follow Mitsuba's conventions (checked against Mitsuba 3's bitmap and
// checkerboard plugins): v = 0 is the file's first (top) row, bilinear filtering interpolates
// between texel centres, to_uv transforms uv before the lookup, and the checkerboard's cell
// (0, 0) has color0. The values come from the kernels (kernels/scene/texture.h).
#include <gtest/gtest.h>

#include "image/image_io.h"
#include "render/device_scene.h"
#include "scene/scene_test_files.h"
#include "support/devices.h"

namespace gdr {
namespace {

constexpr int kW = 2, kH = 4;

// Texel (c, r) of the test bitmap, row r counted from the top of the file.
float texel_r(int c, int) { return 1.0f + c; }
float texel_g(int, int r) { return 10.0f * (1 + r); }

std::vector<cl_float4> lookup(const Scene& scene, int texture, const std::vector<cl_float2>& uv) {
  Context& ctx = test::default_context();
  DeviceScene device(ctx, scene);
  Buffer<cl_float2> in(ctx, uv);
  Buffer<cl_float4> out(ctx, uv.size());
  ctx.program("tests/scene_lookup_test.cl")
      ->kernel("texture_lookup")
      .args(device, texture, cl_uint(uv.size()), in, out)
      .run(uv.size());
  return out.read();
}

cl_float2 uv2(float u, float v) { return cl_float2{{u, v}}; }

Scene bitmap_scene(const test::TempFolder& folder, const std::string& filter, const std::string& extra = "") {
  Image img(kW, kH, {"R", "G", "B"});
  for (int r = 0; r < kH; ++r)
    for (int c = 0; c < kW; ++c) {
      float* p = &img.pixels[3 * (r * kW + c)];
      p[0] = texel_r(c, r);
      p[1] = texel_g(c, r);
      p[2] = 0.0f;
    }
  write_exr(folder.path("tex.exr"), img);
  std::string xml = test::scene_xml(R"(
    <shape type="rectangle"><bsdf type="diffuse"><texture type="bitmap" name="reflectance">
      <string name="filename" value="tex.exr"/><string name="filter_type" value=")" + filter + R"("/>)" +
                                    extra + R"(</texture></bsdf></shape>
    <emitter type="constant"/>)");
  return load_scene(folder.write("scene.xml", xml));
}

TEST(TextureLookup, BitmapRowZeroIsTheTopOfTheFile) {
  test::TempFolder folder;
  for (const char* filter : {"nearest", "bilinear"}) {
    Scene s = bitmap_scene(folder, filter);
    std::vector<cl_float2> uv;
    for (int r = 0; r < kH; ++r)
      for (int c = 0; c < kW; ++c) uv.push_back(uv2((c + 0.5f) / kW, (r + 0.5f) / kH));
    std::vector<cl_float4> got = lookup(s, 0, uv);
    for (int r = 0; r < kH; ++r)
      for (int c = 0; c < kW; ++c) {
        const cl_float4& g = got[r * kW + c];
        EXPECT_NEAR(g.s[0], texel_r(c, r), 1e-4) << filter << " texel " << c << "," << r;
        EXPECT_NEAR(g.s[1], texel_g(c, r), 1e-4) << filter << " texel " << c << "," << r;
      }
  }
}

TEST(TextureLookup, BilinearInterpolatesBetweenTexelCentres) {
  test::TempFolder folder;
  Scene s = bitmap_scene(folder, "bilinear");
  // Half-way between rows 0 and 1 and between the two columns; and at v = 0, where repeat
  // wrapping mixes the first and last rows.
  std::vector<cl_float4> got = lookup(s, 0, {uv2(0.5f, 0.25f), uv2(0.25f, 0.0f)});
  EXPECT_NEAR(got[0].s[0], 0.5f * (texel_r(0, 0) + texel_r(1, 0)), 1e-4);
  EXPECT_NEAR(got[0].s[1], 0.5f * (texel_g(0, 0) + texel_g(0, 1)), 1e-4);
  EXPECT_NEAR(got[1].s[1], 0.5f * (texel_g(0, 0) + texel_g(0, kH - 1)), 1e-4);
}

TEST(TextureLookup, ToUvMovesTheLookupBeforeTheRows) {
  test::TempFolder folder;
  // uv' = (u, v + 1/4): the lookup at v lands one row further down the file.
  Scene s = bitmap_scene(folder, "nearest", R"(<transform name="to_uv"><translate y="0.25"/></transform>)");
  std::vector<cl_float4> got = lookup(s, 0, {uv2(0.25f, 0.125f), uv2(0.75f, 0.625f)});
  EXPECT_NEAR(got[0].s[1], texel_g(0, 1), 1e-4);
  EXPECT_NEAR(got[1].s[1], texel_g(1, 3), 1e-4);
  EXPECT_NEAR(got[1].s[0], texel_r(1, 3), 1e-4);
}

TEST(TextureLookup, CheckerboardCellsAfterToUv) {
  test::TempFolder folder;
  std::string xml = test::scene_xml(R"(
    <shape type="rectangle"><bsdf type="diffuse"><texture type="checkerboard" name="reflectance">
      <rgb name="color0" value="0.9"/><rgb name="color1" value="0.2"/>
      <transform name="to_uv"><scale x="2" y="3"/></transform></texture></bsdf></shape>
    <emitter type="constant"/>)");
  Scene s = load_scene(folder.write("scene.xml", xml));
  // Mitsuba: color0 where the fractional parts of u' and v' are both below or both above 1/2.
  std::vector<cl_float2> uv = {uv2(0.1f, 0.1f), uv2(0.3f, 0.1f), uv2(0.1f, 0.2f), uv2(0.3f, 0.2f), uv2(-0.1f, 0.1f)};
  const float expected[] = {0.9f, 0.2f, 0.2f, 0.9f, 0.2f};
  std::vector<cl_float4> got = lookup(s, 0, uv);
  for (size_t i = 0; i < uv.size(); ++i) EXPECT_FLOAT_EQ(got[i].s[0], expected[i]) << "uv " << uv[i].s[0] << "," << uv[i].s[1];
}

}  // namespace
}  // namespace gdr
