// A shape that emits and has no BSDF is black, as in Mitsuba 0.x and 3 (src/render/shape.cpp);
// a shape with neither keeps Mitsuba's default diffuse 0.5. The energy test: the camera sees
// only an emitting rectangle without a BSDF, lit head-on by a point light a thousand times
// brighter than its own radiance; every pixel is exactly its emitted radiance, since nothing is
// reflected (a 0.5 diffuse would add about 0.5 / pi * 1000 / 1^2).
#include <gtest/gtest.h>

#include "scene/scene_test_files.h"
#include "support/render.h"

namespace gdr {
namespace {

constexpr float kRadiance = 0.25f;

const char* kScene = R"(
  <sensor type="perspective"><float name="fov" value="30"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, 1" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/></film>
  </sensor>
  <shape type="rectangle" id="glowing">
    <transform name="to_world"><scale value="3"/><rotate y="1" angle="180"/><translate z="2"/></transform>
    <emitter type="area"><rgb name="radiance" value="0.25"/></emitter>
  </shape>
  <shape type="rectangle" id="plain"><transform name="to_world"><translate z="-5"/></transform></shape>
  <emitter type="point"><point name="position" x="0" y="0" z="1"/><rgb name="intensity" value="1000"/></emitter>)";

TEST(EmitterWithoutBsdf, MaterialsFollowMitsuba) {
  test::TempFolder folder;
  Scene s = load_scene(folder.write("scene.xml", test::scene_xml(kScene)));
  ASSERT_EQ(s.shapes.size(), 2u);
  const GdrMaterial& glowing = s.materials[s.shapes[0].material];
  const GdrMaterial& plain = s.materials[s.shapes[1].material];
  EXPECT_EQ(glowing.type, BSDF_DIFFUSE);
  EXPECT_EQ(glowing.reflectance[0], 0.0f);
  EXPECT_EQ(plain.type, BSDF_DIFFUSE);
  EXPECT_EQ(plain.reflectance[0], 0.5f);
  EXPECT_GE(s.shapes[0].first_light, 0);
}

TEST(EmitterWithoutBsdf, RendersExactlyItsEmission) {
  test::TempFolder folder;
  Scene s = load_scene(folder.write("scene.xml", test::scene_xml(kScene)));
  RenderSettings rs;
  rs.spp = 4;
  rs.seed = 3;
  rs.max_depth = 8;
  std::vector<float> rgb = test::render_pt(s, rs);
  ASSERT_EQ(rgb.size(), 16u * 16u * 3u);
  for (size_t i = 0; i < rgb.size(); ++i) {
    ASSERT_NEAR(rgb[i], kRadiance, 1e-6f) << "pixel " << i / 3 << " channel " << i % 3;
  }
}

}  // namespace
}  // namespace gdr
