// Parsing of property values, colours, spectra and transforms.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/spectrum.h"
#include "scene/transform.h"
#include "scene/xml_values.h"
#include "scene_test_files.h"
#include "util/error.h"

namespace gdr {
namespace {

// Loads `body` (inside <scene>) and gives the properties of the first element.
struct Parsed {
  XmlDocument doc;
  test::TempFolder folder;
  explicit Parsed(const std::string& body) {
    doc = load_xml_document(folder.write("s.xml", test::scene_xml(body)), {});
  }
  const XmlNode& first() const { return *doc.root->children.front(); }
  Props props() const { return Props(first(), doc); }
};

TEST(XmlValues, ScalarTypes) {
  Parsed p(R"(<bsdf type="x">
      <float name="f" value="-1.5e2"/> <integer name="i" value="42"/>
      <boolean name="b" value="true"/> <string name="s" value="hello world"/>
      <point name="p" x="1" y="2" z="3"/> <vector name="v" value="4, 5 6"/>
    </bsdf>)");
  Props props = p.props();
  EXPECT_DOUBLE_EQ(props.get_float("f", 0), -150.0);
  EXPECT_EQ(props.get_int("i", 0), 42);
  EXPECT_TRUE(props.get_bool("b", false));
  EXPECT_EQ(props.get_string("s", ""), "hello world");
  Vec3d pt = props.get_vec3("p", {});
  EXPECT_EQ(pt.x, 1);
  EXPECT_EQ(pt.z, 3);
  Vec3d v = props.get_vec3("v", {});
  EXPECT_EQ(v.y, 5);
  EXPECT_EQ(v.z, 6);
  EXPECT_DOUBLE_EQ(props.get_float("missing", 7.0), 7.0);
}

TEST(XmlValues, RgbWithOneOrThreeValues) {
  Parsed p(R"(<bsdf type="x">
      <rgb name="a" value="0.25"/> <rgb name="b" value="0.1, 0.2,0.3"/> <rgb name="c" value="0.1 0.2 0.3"/>
      <srgb name="d" value="0.5"/>
    </bsdf>)");
  Props props = p.props();
  Rgb a = props.get_color("a", {}, SpectrumUse::Reflectance);
  EXPECT_FLOAT_EQ(a.r, 0.25f);
  EXPECT_FLOAT_EQ(a.b, 0.25f);
  for (const char* n : {"b", "c"}) {
    Rgb c = props.get_color(n, {}, SpectrumUse::Reflectance);
    EXPECT_FLOAT_EQ(c.r, 0.1f);
    EXPECT_FLOAT_EQ(c.g, 0.2f);
    EXPECT_FLOAT_EQ(c.b, 0.3f);
  }
  // sRGB 0.5 decodes to about 0.214 linear.
  EXPECT_NEAR(props.get_color("d", {}, SpectrumUse::Reflectance).g, 0.2140, 1e-3);
}

TEST(XmlValues, SpectrumPairsGiveSensibleColours) {
  Parsed p(R"(<bsdf type="x">
      <spectrum name="red" value="400:0.05, 550:0.05, 600:0.6, 700:0.65"/>
      <spectrum name="blue" value="400:0.7, 480:0.6, 520:0.05, 700:0.05"/>
      <spectrum name="const" value="0.3"/>
    </bsdf>)");
  Props props = p.props();
  Rgb red = props.get_color("red", {}, SpectrumUse::Reflectance);
  EXPECT_GT(red.r, 3 * red.g);
  EXPECT_GT(red.r, 3 * red.b);
  EXPECT_LT(red.r, 1.0f);  // saturated spectra may exceed their maximum in one sRGB channel
  Rgb blue = props.get_color("blue", {}, SpectrumUse::Reflectance);
  EXPECT_GT(blue.b, 2 * blue.r);
  Rgb k = props.get_color("const", {}, SpectrumUse::Reflectance);
  EXPECT_FLOAT_EQ(k.g, 0.3f);
}

TEST(XmlValues, TransformsComposeInOrder) {
  Parsed p(R"(<shape type="x"><transform name="to_world">
      <scale value="2"/> <rotate z="1" angle="90"/> <translate x="1" y="2" z="3"/>
    </transform></shape>)");
  Mat4d m = p.props().get_transform("to_world");
  // By hand: (1,0,0) -> scale (2,0,0) -> rotate about z by 90 (0,2,0) -> translate (1,4,3).
  Vec3d q = m.point({1, 0, 0});
  EXPECT_NEAR(q.x, 1, 1e-12);
  EXPECT_NEAR(q.y, 4, 1e-12);
  EXPECT_NEAR(q.z, 3, 1e-12);
  const double expected[3][4] = {{0, -2, 0, 1}, {2, 0, 0, 2}, {0, 0, 2, 3}};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(m.m[r][c], expected[r][c], 1e-12) << r << "," << c;
}

TEST(XmlValues, MatrixAndScaleForms) {
  Parsed p(R"(<shape type="x"><transform name="to_world">
      <matrix value="1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1"/> <scale x="-1"/> <scale value="1 2 3"/>
    </transform></shape>)");
  Mat4d m = p.props().get_transform("to_world");
  Vec3d q = m.point({0, 0, 0});
  EXPECT_NEAR(q.x, -5, 1e-12);  // translate, mirror x, then scale (1, 2, 3)
  EXPECT_NEAR(q.y, 12, 1e-12);
  EXPECT_NEAR(q.z, 21, 1e-12);
}

TEST(XmlValues, LookAtFrameConvention) {
  Mat4d m = Mat4d::look_at({0, 0, 0}, {0, 0, 5}, {0, 1, 0});
  // Camera space: +z forward, +y up, +x left (Mitsuba): looking along +z with y up, left is +x.
  Vec3d fwd = m.vector({0, 0, 1}), up = m.vector({0, 1, 0}), left = m.vector({1, 0, 0});
  EXPECT_NEAR(fwd.z, 1, 1e-12);
  EXPECT_NEAR(up.y, 1, 1e-12);
  EXPECT_NEAR(left.x, 1, 1e-12);
  Mat4d n = Mat4d::look_at({1, 2, 3}, {1, 2, 2}, {0, 1, 0});  // looking along -z: left is -x
  EXPECT_NEAR(n.vector({1, 0, 0}).x, -1, 1e-12);
  EXPECT_NEAR(n.translation().z, 3, 1e-12);
}

TEST(XmlValues, InverseAndNormalTransform) {
  Mat4d m = Mat4d::translate({1, 2, 3}) * Mat4d::rotate({1, 1, 0}, 30) * Mat4d::scale({1, 4, 2});
  Mat4d id = m * m.inverse();
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(id.m[r][c], r == c ? 1.0 : 0.0, 1e-12);
  // A normal stays perpendicular to transformed tangents.
  Vec3d t1 = m.vector({1, -1, 0}), t2 = m.vector({0, 1, 1});
  Vec3d n = m.normal(normalize(cross({1, -1, 0}, {0, 1, 1})));
  EXPECT_NEAR(dot(n, t1), 0, 1e-12);
  EXPECT_NEAR(dot(n, t2), 0, 1e-12);
}

TEST(XmlValues, BadNumberNamesFileLineAndAttribute) {
  test::TempFolder folder;
  std::string path = folder.write("bad.xml", test::scene_xml(R"(<shape type="sphere">
    <float name="radius" value="1.0x"/>
  </shape>)"));
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_EQ(e.line(), 3) << msg;
    EXPECT_NE(msg.find("bad.xml:3"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'value'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("1.0x"), std::string::npos) << msg;
  }
}

TEST(XmlValues, WrongCountsAreErrors) {
  test::TempFolder folder;
  for (const char* body : {R"(<bsdf type="diffuse" id="a"><rgb name="reflectance" value="1 2"/></bsdf>
                              <shape type="cube"><ref id="a"/></shape>)",
                           R"(<shape type="cube"><transform name="to_world"><matrix value="1 2 3"/></transform></shape>)",
                           R"(<shape type="cube"><transform name="to_world"><rotate angle="3"/></transform></shape>)"}) {
    EXPECT_THROW(load_scene(folder.write("s.xml", test::scene_xml(body))), InputError) << body;
  }
}

}  // namespace
}  // namespace gdr
