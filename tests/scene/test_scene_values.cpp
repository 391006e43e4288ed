// Values that must not pass silently: colours that are not finite or negative are errors naming
// file and line; reflectances above 1 are clamped with a warning; a negative envmap scale is an
// error; unknown parameters and versions, a scene without emitters, an empty mesh and a replaced
// up vector are warnings naming file and line (unknown parameters are errors with --strict);
// Mitsuba's direct integrator is path tracing of two segments; Embree's robust mode is a scene
// property.
#include <gtest/gtest.h>

#include "scene/load_scene.h"
#include "scene/scene_test_files.h"
#include "util/error.h"

namespace gdr {
namespace {
using test::all_warnings;
using test::has_warning;

const char* kLight = R"(<emitter type="point"><point name="position" x="0" y="2" z="0"/></emitter>)";

Scene load(const test::TempFolder& folder, const std::string& body, bool strict = false,
           const std::string& version = "3.0.0") {
  LoadOptions o;
  o.strict = strict;
  return load_scene(folder.write("s.xml", test::scene_xml("<sensor type=\"perspective\"/>\n" + body, version)), o);
}

// The load fails with an InputError whose message names s.xml, `line` and every key word.
void expect_error(const test::TempFolder& folder, const std::string& body, int line,
                  const std::vector<std::string>& words, bool strict = false) {
  try {
    load(folder, body, strict);
    FAIL() << "no error for: " << body;
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("s.xml:" + std::to_string(line)), std::string::npos) << msg;
    for (const std::string& w : words) EXPECT_NE(msg.find(w), std::string::npos) << msg;
  }
}

TEST(SceneValues, NonFiniteOrNegativeColoursAreErrors) {
  test::TempFolder folder;
  // Line 4: the <rgb> (line 1 <scene>, line 2 <sensor>, line 3 light, shape and bsdf).
  for (const char* value : {"nan", "inf", "-0.5", "0.5, -1, 0.5"}) {
    SCOPED_TRACE(value);
    expect_error(folder, std::string(kLight) + "<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<rgb name=\"reflectance\" value=\"" +
                             value + "\"/></bsdf></shape>",
                 4, {"reflectance"});
  }
  expect_error(folder, std::string(kLight) + "\n<shape type=\"sphere\"><emitter type=\"area\">\n"
                                             "<rgb name=\"radiance\" value=\"-1\"/></emitter></shape>",
               5, {"radiance", "negative"});
}

TEST(SceneValues, ReflectanceAboveOneIsClampedWithAWarning) {
  test::TempFolder folder;
  Scene s = load(folder, std::string(kLight) + "\n<shape type=\"sphere\"><bsdf type=\"diffuse\">\n"
                                                "<rgb name=\"reflectance\" value=\"2, 0.5, 1.5\"/></bsdf></shape>");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].reflectance[0], 1.0f);
  EXPECT_EQ(s.materials[0].reflectance[1], 0.5f);
  EXPECT_EQ(s.materials[0].reflectance[2], 1.0f);
  EXPECT_TRUE(has_warning(s, {"s.xml:5", "reflectance", "clamped"})) << all_warnings(s);
}

TEST(SceneValues, NegativeEnvmapScaleIsAnError) {
  test::TempFolder folder;
  expect_error(folder, "<emitter type=\"envmap\"><string name=\"filename\" value=\"none.exr\"/>\n"
                       "<float name=\"scale\" value=\"-2\"/></emitter>",
               4, {"scale", "negative"});
}

// Mitsuba 3 refuses anisotropic roughplastic (its coating table depends on cos(theta) only).
TEST(SceneValues, AnisotropicRoughPlasticIsAnError) {
  test::TempFolder folder;
  expect_error(folder, std::string(kLight) + "<shape type=\"sphere\"><bsdf type=\"roughplastic\">\n"
                                             "<float name=\"alpha_u\" value=\"0.1\"/><float name=\"alpha_v\" value=\"0.3\"/>"
                                             "</bsdf></shape>",
               4, {"roughplastic", "anisotropic"});
  // Equal alphas given one by one are isotropic.
  Scene s = load(folder, std::string(kLight) + "<shape type=\"sphere\"><bsdf type=\"roughplastic\">\n"
                                               "<float name=\"alpha_u\" value=\"0.2\"/><float name=\"alpha_v\" value=\"0.2\"/>"
                                               "</bsdf></shape>");
  const GdrMaterial& m = s.materials.at(s.shapes.at(0).material);
  EXPECT_EQ(m.type, BSDF_ROUGH_PLASTIC);
  EXPECT_FLOAT_EQ(m.alpha_u, 0.2f);
}

TEST(SceneValues, UnknownParameterIsAWarningOrStrictError) {
  test::TempFolder folder;
  std::string body = std::string(kLight) + "\n<shape type=\"sphere\"><bsdf type=\"diffuse\">\n"
                                           "<rgb name=\"reflectanse\" value=\"0.3\"/></bsdf></shape>";
  Scene s = load(folder, body);
  EXPECT_TRUE(has_warning(s, {"s.xml:4", "reflectanse", "diffuse"})) << all_warnings(s);
  expect_error(folder, body, 4, {"reflectanse"}, true);
}

TEST(SceneValues, KnownParametersDoNotWarn) {
  test::TempFolder folder;
  Scene s = load(folder, std::string(kLight) + R"(
<integrator type="path"><integer name="max_depth" value="5"/><integer name="rr_depth" value="5"/></integrator>
<shape type="sphere"><float name="radius" value="2"/><bsdf type="roughplastic"><float name="alpha" value="0.2"/>
<rgb name="diffuse_reflectance" value="0.4"/><string name="distribution" value="ggx"/></bsdf></shape>)");
  EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
}

// Mitsuba 3's scene-level embree_use_robust_intersections (off unless given); another value at
// the scene's top level is an unknown parameter.
TEST(SceneValues, RobustIntersectionsAreASceneProperty) {
  test::TempFolder folder;
  std::string shape = std::string(kLight) + "<shape type=\"sphere\"/>";
  EXPECT_FALSE(load(folder, shape).robust_intersections);
  Scene s = load(folder, shape + "\n<boolean name=\"embree_use_robust_intersections\" value=\"true\"/>");
  EXPECT_TRUE(s.robust_intersections);
  EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
  Scene typo = load(folder, shape + "\n<boolean name=\"embree_use_robust\" value=\"true\"/>");
  EXPECT_FALSE(typo.robust_intersections);
  EXPECT_TRUE(has_warning(typo, {"s.xml:4", "embree_use_robust"})) << all_warnings(typo);
}

TEST(SceneValues, DirectIntegratorIsTwoSegmentPathTracing) {
  test::TempFolder folder;
  Scene s = load(folder, std::string(kLight) + "<integrator type=\"direct\"/><shape type=\"sphere\"/>");
  EXPECT_EQ(s.integrator, "path");
  EXPECT_EQ(s.max_depth, 2);
}

TEST(SceneValues, MaxDepthZeroIsKeptAndBelowMinusOneIsAnError) {
  test::TempFolder folder;
  Scene s = load(folder, std::string(kLight) + "<integrator type=\"path\"><integer name=\"max_depth\" value=\"0\"/>"
                                               "</integrator><shape type=\"sphere\"/>");
  EXPECT_EQ(s.max_depth, 0);
  expect_error(folder, "<integrator type=\"path\">\n<integer name=\"max_depth\" value=\"-3\"/></integrator>", 3,
               {"max_depth"});
}

TEST(SceneValues, SuspiciousScenesWarn) {
  test::TempFolder folder;
  Scene dark = load(folder, "<shape type=\"sphere\"/>");
  EXPECT_TRUE(has_warning(dark, {"no emitter"})) << all_warnings(dark);

  folder.write("empty.obj", "# no faces\nv 0 0 0\n");
  Scene empty = load(folder, std::string(kLight) + "<shape type=\"obj\"><string name=\"filename\" value=\"empty.obj\"/></shape>");
  EXPECT_TRUE(has_warning(empty, {"obj", "no triangles"})) << all_warnings(empty);

  Scene up = load(folder, std::string(kLight) + R"(
<shape type="sphere"><transform name="to_world">
<lookat origin="0, 5, 0" target="0, 0, 0" up="0, 1, 0"/></transform></shape>)");
  EXPECT_TRUE(has_warning(up, {"s.xml:5", "up vector"})) << all_warnings(up);

  Scene version = load(folder, std::string(kLight) + "<shape type=\"sphere\"/>", false, "7.1.0");
  EXPECT_TRUE(has_warning(version, {"s.xml:1", "version"})) << all_warnings(version);
}

}  // namespace
}  // namespace gdr
