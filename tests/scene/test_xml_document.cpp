// Document-level features: includes, defaults and overrides, references, paths, line numbers,
// the 0.6 dialect, and the errors of each.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/load_scene.h"
#include "scene/xml_document.h"
#include "scene_test_files.h"
#include "util/error.h"

namespace gdr {
namespace {

const char* kCamera = R"(<sensor type="perspective"><float name="fov" value="$fov"/>
    <film type="hdrfilm"><integer name="width" value="$res"/><integer name="height" value="$res"/></film>
  </sensor>)";

// The message of the InputError that loading `path` throws ("" when it loads).
std::string load_error(const std::string& path, const LoadOptions& options = {}) {
  try {
    load_scene(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(XmlDocument, SnakeCaseOfCamelCaseNames) {
  EXPECT_EQ(snake_case("toWorld"), "to_world");
  EXPECT_EQ(snake_case("intIOR"), "int_ior");
  EXPECT_EQ(snake_case("sampleCount"), "sample_count");
  EXPECT_EQ(snake_case("to_world"), "to_world");
}

TEST(XmlDocument, DefaultsSubstituteAndCanBeOverridden) {
  test::TempFolder folder;
  std::string path = folder.write("s.xml", test::scene_xml(std::string(R"(<default name="res" value="32"/>
    <default name="fov" value="30"/>)") + kCamera));
  Scene s = load_scene(path);
  EXPECT_EQ(s.camera.width, 32);
  LoadOptions options;
  options.defines["res"] = "48";
  s = load_scene(path, options);
  EXPECT_EQ(s.camera.width, 48);
  EXPECT_EQ(s.camera.height, 48);
}

TEST(XmlDocument, UndefinedParameterIsAnError) {
  test::TempFolder folder;
  std::string msg = load_error(folder.write("s.xml", test::scene_xml(kCamera)));
  EXPECT_NE(msg.find("$fov"), std::string::npos) << msg;
}

TEST(XmlDocument, IncludesResolveAgainstTheTopLevelFolder) {
  test::TempFolder folder;
  // The fragment lives in sub/ but names its mesh relative to the top-level scene's folder.
  folder.write("meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  folder.write("sub/fragment.xml", test::scene_xml(R"(<default name="spp" value="5"/>
    <bsdf type="diffuse" id="grey"><rgb name="reflectance" value="0.3"/></bsdf>
    <shape type="obj"><string name="filename" value="meshes/tri.obj"/><ref id="grey"/></shape>)"));
  std::string path = folder.write("s.xml", test::scene_xml(R"(<include filename="sub/fragment.xml"/>
    <sensor type="perspective"><sampler type="independent"><integer name="sample_count" value="$spp"/></sampler></sensor>
    <shape type="rectangle"><ref id="grey"/></shape>)"));
  Scene s = load_scene(path);
  EXPECT_EQ(s.spp, 5);
  ASSERT_EQ(s.shapes.size(), 2u);
  EXPECT_EQ(s.shapes[0].material, s.shapes[1].material);  // one material for one <bsdf id>
  EXPECT_EQ(s.materials.size(), 1u);
  EXPECT_FLOAT_EQ(s.materials[0].reflectance[0], 0.3f);
}

TEST(XmlDocument, PathElementAddsASearchFolder) {
  test::TempFolder folder;
  folder.write("data/meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::string path = folder.write("scenes/s.xml", test::scene_xml(R"(<path value="../data"/>
    <shape type="obj"><string name="filename" value="meshes/tri.obj"/></shape>)"));
  EXPECT_EQ(load_scene(path).triangles.size(), 1u);
}

TEST(XmlDocument, NamedAndForwardReferences) {
  test::TempFolder folder;
  std::string path = folder.write("s.xml", test::scene_xml(R"(<sensor type="perspective"/>
    <shape type="rectangle"><ref name="bsdf" id="b"/><ref id="light"/></shape>
    <texture type="checkerboard" id="tex"/>
    <bsdf type="diffuse" id="b"><ref name="reflectance" id="tex"/></bsdf>
    <emitter type="area" id="light"><rgb name="radiance" value="2"/></emitter>)"));
  Scene s = load_scene(path);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].reflectance_texture, 0);
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.textures[0].type, TEXTURE_CHECKERBOARD);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_FLOAT_EQ(s.lights[1].radiance[2], 2.0f);
  EXPECT_EQ(s.shapes[0].first_light, 0);
}

TEST(XmlDocument, MalformedXmlNamesItsLine) {
  test::TempFolder folder;
  std::string path = folder.write("broken.xml", "<scene version=\"3.0.0\">\n  <shape type=\"cube\">\n"
                                                "  </shap>\n</scene>\n");
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 3) << e.what();
    EXPECT_NE(std::string(e.what()).find("malformed XML"), std::string::npos) << e.what();
  }
}

TEST(XmlDocument, MissingIncludeNamesTheIncludingLine) {
  test::TempFolder folder;
  std::string path = folder.write("s.xml", "<scene version=\"3.0.0\">\n\n  <include filename=\"nope.xml\"/>\n</scene>");
  try {
    load_scene(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("nope.xml"), std::string::npos) << e.what();
  }
}

TEST(XmlDocument, MissingMeshFileIsAnError) {
  test::TempFolder folder;
  std::string msg = load_error(folder.write("s.xml", test::scene_xml(
      R"(<shape type="obj"><string name="filename" value="gone.obj"/></shape>)")));
  EXPECT_NE(msg.find("s.xml:2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("missing file 'gone.obj'"), std::string::npos) << msg;
}

TEST(XmlDocument, UnknownReferenceIsAnError) {
  test::TempFolder folder;
  std::string msg = load_error(folder.write("s.xml", test::scene_xml(
      R"(<shape type="cube"><ref id="nothing"/></shape>)")));
  EXPECT_NE(msg.find("unknown reference id 'nothing'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("s.xml:2"), std::string::npos) << msg;
}

TEST(XmlDocument, IncludeCycleIsAnError) {
  test::TempFolder folder;
  folder.write("a.xml", test::scene_xml(R"(<include filename="b.xml"/>)"));
  folder.write("b.xml", test::scene_xml(R"(<include filename="a.xml"/>)"));
  EXPECT_NE(load_error(folder.path("a.xml")).find("include cycle"), std::string::npos);
}

TEST(XmlDocument, Mitsuba06Dialect) {
  test::TempFolder folder;
  folder.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::string path = folder.write("s.xml", test::scene_xml(R"(
    <integrator type="path"><integer name="maxDepth" value="7"/></integrator>
    <sensor type="perspective">
      <float name="fov" value="60"/><string name="fovAxis" value="y"/>
      <float name="nearClip" value="0.5"/><float name="farClip" value="50"/>
      <transform name="toWorld"><translate x="1"/></transform>
      <sampler type="ldsampler"><integer name="sampleCount" value="9"/></sampler>
      <film type="ldrfilm"><integer name="width" value="40"/><integer name="height" value="20"/></film>
    </sensor>
    <shape type="obj"><string name="filename" value="tri.obj"/><boolean name="faceNormals" value="true"/>
      <transform name="toWorld"><scale value="2"/></transform>
      <bsdf type="roughdielectric"><float name="intIOR" value="1.33"/><float name="extIOR" value="1.0"/>
        <float name="alphaU" value="0.1"/><float name="alphaV" value="0.3"/></bsdf>
    </shape>
    <emitter type="spot"><rgb name="intensity" value="5"/><float name="cutoffAngle" value="30"/>
      <float name="beamWidth" value="10"/><transform name="toWorld"><lookat origin="0 5 0" target="0 0 0" up="0 0 1"/></transform>
    </emitter>)", "0.6.0"));
  Scene s = load_scene(path);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  EXPECT_EQ(s.max_depth, 7);
  EXPECT_EQ(s.spp, 9);
  EXPECT_EQ(s.camera.width, 40);
  EXPECT_NEAR(s.camera.tan_half_fov_y, std::tan(M_PI / 6), 1e-6);
  EXPECT_NEAR(s.camera.tan_half_fov_x, 2 * std::tan(M_PI / 6), 1e-6);
  EXPECT_FLOAT_EQ(s.camera.near_clip, 0.5f);
  EXPECT_FLOAT_EQ(s.camera.to_world[3], 1.0f);
  EXPECT_FLOAT_EQ(s.positions[1].x, 2.0f);
  const GdrMaterial& m = s.materials[0];
  EXPECT_EQ(m.type, BSDF_ROUGH_DIELECTRIC);
  EXPECT_NEAR(m.eta[0], 1.33f, 1e-6);
  EXPECT_FLOAT_EQ(m.alpha_u, 0.1f);
  EXPECT_FLOAT_EQ(m.alpha_v, 0.3f);
  ASSERT_EQ(s.lights.size(), 1u);
  const GdrLight& l = s.lights[0];
  EXPECT_EQ(l.type, LIGHT_SPOT);
  EXPECT_NEAR(l.cos_cutoff, std::cos(30 * M_PI / 180), 1e-6);
  EXPECT_NEAR(l.cos_falloff, std::cos(10 * M_PI / 180), 1e-6);
  EXPECT_NEAR(l.direction[1], -1.0f, 1e-6);  // spot looks along its local +z
  EXPECT_NEAR(l.position[1], 5.0f, 1e-6);
}

}  // namespace
}  // namespace gdr
