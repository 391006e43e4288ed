// What the loader puts into Scene: analytic shapes, materials and their defaults, textures,
// emitters, the sensor, unsupported features (warning vs --strict) and the description.
#include <gtest/gtest.h>

#include <cmath>

#include "image/image.h"
#include "image/image_io.h"
#include "scene/describe_scene.h"
#include "scene/load_scene.h"
#include "scene/named_conductors.h"
#include "scene_test_files.h"
#include "util/error.h"

namespace gdr {
namespace {

Scene load_body(const test::TempFolder& folder, const std::string& body, const LoadOptions& options = {},
                const std::string& version = "3.0.0") {
  return load_scene(folder.write("s.xml", test::scene_xml("<sensor type=\"perspective\"/>\n" + body, version)),
                    options);
}

double triangle_area(const Scene& s, const GdrTriangle& t, double n[3]) {
  const Vec4 &a = s.positions[t.v[0]], &b = s.positions[t.v[1]], &c = s.positions[t.v[2]];
  double e1[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, e2[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
  n[0] = e1[1] * e2[2] - e1[2] * e2[1];
  n[1] = e1[2] * e2[0] - e1[0] * e2[2];
  n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

TEST(SceneShapes, SphereAreaAndOutwardNormals) {
  test::TempFolder folder;
  Scene s = load_body(folder, R"(<shape type="sphere"><point name="center" x="1" y="2" z="3"/>
    <float name="radius" value="2"/></shape><emitter type="constant"/>)");
  double area = 0;
  for (const GdrTriangle& t : s.triangles) {
    double n[3];
    area += triangle_area(s, t, n);
    const Vec4& a = s.positions[t.v[0]];
    // The geometric normal points away from the centre.
    EXPECT_GT(n[0] * (a.x - 1) + n[1] * (a.y - 2) + n[2] * (a.z - 3), 0.0);
  }
  // A 64 x 128 tessellation is within 0.1% of 4 pi r^2 (from below: inscribed polygons).
  EXPECT_NEAR(area / (4 * M_PI * 4), 1.0, 1e-3);
  EXPECT_LT(area, 4 * M_PI * 4);
  EXPECT_TRUE(s.shapes[0].flags & SHAPE_HAS_NORMALS);
  const Vec4 &p = s.positions[100], &n = s.normals[100];
  EXPECT_NEAR(n.x * 2, p.x - 1, 1e-5);
  EXPECT_NEAR(n.z * 2, p.z - 3, 1e-5);
  EXPECT_TRUE(s.warnings.empty());
}

TEST(SceneShapes, RectangleNormalAndFlip) {
  test::TempFolder folder;
  Scene s = load_body(folder, R"(
    <shape type="rectangle"><transform name="to_world"><rotate x="1" angle="-90"/></transform></shape>
    <shape type="rectangle"><boolean name="flip_normals" value="true"/></shape>)");
  ASSERT_EQ(s.shapes.size(), 2u);
  double n[3];
  triangle_area(s, s.triangles[0], n);
  EXPECT_GT(n[1], 0);  // +z rotated by -90 about x is +y
  EXPECT_NEAR(s.normals[0].y, 1.0f, 1e-6);
  EXPECT_FALSE(s.shapes[0].flags & SHAPE_FLIP_NORMALS);
  // Flipped: the data stay, the flag tells the kernels to negate both normals (-z).
  EXPECT_TRUE(s.shapes[1].flags & SHAPE_FLIP_NORMALS);
  triangle_area(s, s.triangles[2], n);
  EXPECT_GT(n[2], 0);
}

TEST(SceneShapes, CubeFacesPointOutward) {
  test::TempFolder folder;
  Scene s = load_body(folder, R"(<shape type="cube"/><shape type="disk"/>)");
  EXPECT_EQ(s.shapes[0].triangle_count, 12);
  double area = 0;
  for (int i = 0; i < 12; ++i) {
    double n[3];
    area += triangle_area(s, s.triangles[i], n);
    const Vec4& a = s.positions[s.triangles[i].v[0]];
    const Vec4& b = s.positions[s.triangles[i].v[1]];
    const Vec4& c = s.positions[s.triangles[i].v[2]];
    double centre[3] = {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
    EXPECT_GT(n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2], 0.0) << i;
  }
  EXPECT_NEAR(area, 24.0, 1e-9);
  double disk = 0;
  for (int i = 0; i < s.shapes[1].triangle_count; ++i) {
    double n[3];
    disk += triangle_area(s, s.triangles[s.shapes[1].first_triangle + i], n);
    EXPECT_GT(n[2], 0);
  }
  EXPECT_NEAR(disk / M_PI, 1.0, 2e-3);
}

TEST(SceneShapes, MeshWithoutNormalsKeepsZeroNormalsAndFlags) {
  test::TempFolder folder;
  folder.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 1 1 2\n");
  Scene s = load_body(folder, R"(
    <shape type="obj"><string name="filename" value="tri.obj"/><boolean name="face_normals" value="true"/>
      <transform name="to_world"><scale value="3"/></transform></shape><emitter type="constant"/>)");
  EXPECT_EQ(s.normals.size(), s.positions.size());
  EXPECT_EQ(s.uvs.size(), 2 * s.positions.size());
  EXPECT_FALSE(s.shapes[0].flags & SHAPE_HAS_NORMALS);
  EXPECT_FALSE(s.shapes[0].flags & SHAPE_HAS_UVS);
  for (const Vec4& n : s.normals) EXPECT_EQ(n.x * n.x + n.y * n.y + n.z * n.z, 0.0f);
  EXPECT_FLOAT_EQ(s.positions[1].x, 3.0f);
  // The degenerate second triangle is kept and counted in a warning.
  EXPECT_EQ(s.triangles.size(), 2u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("1 degenerate"), std::string::npos) << s.warnings[0];
}

TEST(SceneMaterials, DefaultsFollowMitsuba) {
  test::TempFolder folder;
  Scene s = load_body(folder, R"(<shape type="cube"/>
    <shape type="cube"><bsdf type="roughconductor"/></shape>
    <shape type="cube"><bsdf type="plastic"/></shape>
    <shape type="cube"><bsdf type="dielectric"/></shape>
    <shape type="cube"><bsdf type="twosided"><bsdf type="roughplastic"/></bsdf></shape>)");
  ASSERT_EQ(s.materials.size(), 5u);
  const GdrMaterial& d = s.materials[s.shapes[0].material];
  EXPECT_EQ(d.type, BSDF_DIFFUSE);
  EXPECT_FLOAT_EQ(d.reflectance[1], 0.5f);
  EXPECT_EQ(d.reflectance_texture, -1);
  const GdrMaterial& rc = s.materials[s.shapes[1].material];
  EXPECT_EQ(rc.distribution, MICROFACET_BECKMANN);
  EXPECT_FLOAT_EQ(rc.alpha_u, 0.1f);
  EXPECT_FLOAT_EQ(rc.eta[0], 0.0f);  // Mitsuba 3's default material "none": perfect mirror
  EXPECT_FLOAT_EQ(rc.k[0], 1.0f);
  const GdrMaterial& pl = s.materials[s.shapes[2].material];
  EXPECT_NEAR(pl.eta[0], 1.49f / 1.000277f, 1e-6);
  EXPECT_FLOAT_EQ(pl.reflectance[0], 0.5f);
  EXPECT_EQ(pl.nonlinear, 0);
  const GdrMaterial& di = s.materials[s.shapes[3].material];
  EXPECT_NEAR(di.eta[0], 1.5046f / 1.000277f, 1e-6);
  EXPECT_FLOAT_EQ(di.specular_transmittance[2], 1.0f);
  const GdrMaterial& two = s.materials[s.shapes[4].material];
  EXPECT_EQ(two.type, BSDF_ROUGH_PLASTIC);
  EXPECT_EQ(two.twosided, 1);
  EXPECT_EQ(s.materials[s.shapes[1].material].twosided, 0);
}

TEST(SceneMaterials, NamedConductorsAndIors) {
  test::TempFolder folder;
  Scene s = load_body(folder, R"(
    <shape type="cube"><bsdf type="conductor"><string name="material" value="Au"/></bsdf></shape>
    <shape type="cube"><bsdf type="roughconductor"><string name="material" value="Al"/>
      <string name="distribution" value="ggx"/><float name="alpha_u" value="0.05"/><float name="alpha_v" value="0.2"/></bsdf></shape>
    <shape type="cube"><bsdf type="dielectric"><string name="int_ior" value="water"/><float name="ext_ior" value="1.0"/></bsdf></shape>
    <shape type="cube"><bsdf type="thindielectric"><string name="int_ior" value="diamond"/><string name="ext_ior" value="vacuum"/></bsdf></shape>
    <shape type="cube"><bsdf type="conductor"><rgb name="eta" value="0.2, 0.9, 1.1"/><rgb name="k" value="3.9 2.4 2.1"/></bsdf></shape>)");
  const GdrMaterial& au = s.materials[0];
  EXPECT_EQ(au.type, BSDF_CONDUCTOR);
  EXPECT_NEAR(au.eta[0], 0.143f, 1e-3);  // gold: low eta in red, high k
  EXPECT_NEAR(au.k[0], 3.983f, 1e-3);
  EXPECT_LT(au.eta[0], au.eta[2]);
  const GdrMaterial& al = s.materials[1];
  EXPECT_EQ(al.distribution, MICROFACET_GGX);
  EXPECT_FLOAT_EQ(al.alpha_u, 0.05f);
  EXPECT_FLOAT_EQ(al.alpha_v, 0.2f);
  EXPECT_NEAR(al.k[1], 6.27f, 1e-2);
  EXPECT_NEAR(s.materials[2].eta[0], 1.333f, 1e-4);
  EXPECT_NEAR(s.materials[3].eta[0], 2.419f, 1e-4);
  EXPECT_FLOAT_EQ(s.materials[4].eta[1], 0.9f);
  EXPECT_FLOAT_EQ(s.materials[4].k[2], 2.1f);
}

TEST(SceneMaterials, Mitsuba06ConductorDefaultsToCopper) {
  test::TempFolder folder;
  Scene s = load_body(folder, R"(<shape type="cube"><bsdf type="conductor"/></shape>)", {}, "0.6.0");
  ComplexIor cu{};
  ASSERT_TRUE(named_conductor("Cu", &cu));
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(s.materials[0].eta[i], cu.eta[i]);
    EXPECT_EQ(s.materials[0].k[i], cu.k[i]);
  }
}

TEST(SceneMaterials, UnknownNamesAreErrors) {
  test::TempFolder folder;
  for (const char* body : {R"(<shape type="cube"><bsdf type="dielectric"><string name="int_ior" value="unobtainium"/></bsdf></shape>)",
                           R"(<shape type="cube"><bsdf type="conductor"><string name="material" value="Xx"/></bsdf></shape>)"}) {
    try {
      load_body(folder, body);
      ADD_FAILURE() << "no error for " << body;
    } catch (const InputError& e) {
      std::string msg = e.what();
      EXPECT_NE(msg.find("s.xml:3"), std::string::npos) << msg;
      EXPECT_TRUE(msg.find("unobtainium") != std::string::npos || msg.find("'Xx'") != std::string::npos) << msg;
    }
  }
}

TEST(SceneUnsupported, WarningNamesElementAndSubstituteOrStrictError) {
  test::TempFolder folder;
  std::string body = R"(<shape type="cube"><bsdf type="principled"/></shape>
    <shape type="cube"><bsdf type="bumpmap"><texture type="bitmap" name="arbitrary"/>
      <bsdf type="conductor"/></bsdf></shape>
    <medium type="homogeneous" id="fog"/><emitter type="constant"/>)";
  Scene s = load_body(folder, body);
  ASSERT_EQ(s.warnings.size(), 3u);
  EXPECT_NE(s.warnings[0].find("<bsdf type=\"principled\"> at "), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("s.xml:3"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[0].find("50% grey diffuse"), std::string::npos) << s.warnings[0];
  EXPECT_EQ(s.materials[s.shapes[0].material].type, BSDF_DIFFUSE);
  EXPECT_EQ(s.materials[s.shapes[1].material].type, BSDF_CONDUCTOR);  // bumpmap: its nested BSDF
  EXPECT_NE(s.warnings[2].find("medium"), std::string::npos) << s.warnings[2];
  LoadOptions strict;
  strict.strict = true;
  try {
    load_body(folder, body, strict);
    FAIL() << "strict mode accepted an unsupported BSDF";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("principled"), std::string::npos) << e.what();
  }
}

TEST(SceneTextures, BitmapIsDecodedToLinearAndCheckerboard) {
  test::TempFolder folder;
  Image img(2, 1, {"R", "G", "B"});
  img.pixels = {0.5f, 0.5f, 0.5f, 1.0f, 0.0f, 0.0f};  // written as 8-bit sRGB
  write_png(folder.path("tex.png"), img);
  Scene s = load_body(folder, R"(
    <shape type="rectangle"><bsdf type="diffuse"><texture type="bitmap" name="reflectance">
      <string name="filename" value="tex.png"/><string name="filter_type" value="nearest"/>
      <transform name="to_uv"><scale x="2" y="3"/></transform></texture></bsdf></shape>
    <shape type="rectangle"><bsdf type="plastic"><texture type="checkerboard" name="diffuse_reflectance">
      <rgb name="color0" value="0.9"/></texture></bsdf></shape>)");
  ASSERT_EQ(s.textures.size(), 2u);
  const GdrTexture& t = s.textures[0];
  EXPECT_EQ(t.type, TEXTURE_BITMAP);
  EXPECT_EQ(t.width, 2);
  EXPECT_EQ(t.bilinear, 0);
  EXPECT_FLOAT_EQ(t.uv_transform[0], 2.0f);
  EXPECT_FLOAT_EQ(t.uv_transform[4], 3.0f);
  // The PNG holds sRGB 0.5 (8-bit): stored linear, about 0.5 again after encode/decode.
  EXPECT_NEAR(s.texels[t.offset].x, 0.5f, 0.01f);
  EXPECT_NEAR(s.texels[t.offset + 1].x, 1.0f, 1e-6);
  EXPECT_EQ(s.materials[0].reflectance_texture, 0);
  EXPECT_EQ(s.materials[1].reflectance_texture, 1);
  EXPECT_FLOAT_EQ(s.textures[1].color0[0], 0.9f);
  EXPECT_FLOAT_EQ(s.textures[1].color1[0], 0.2f);
  EXPECT_TRUE(s.features.textures);
  EXPECT_EQ(s.features.kernel_defines().count("GDR_TEXTURES"), 1u);
}

TEST(SceneEmitters, PointSpotDirectionalEnvmap) {
  test::TempFolder folder;
  Image env(4, 2, {"R", "G", "B"});
  env.pixels.assign(4 * 2 * 3, 2.0f);
  write_exr(folder.path("sky.exr"), env);
  Scene s = load_body(folder, R"(<shape type="cube"/>
    <emitter type="point"><point name="position" x="1" y="2" z="3"/><rgb name="intensity" value="10"/></emitter>
    <emitter type="spot"><transform name="to_world"><lookat origin="0 0 5" target="0 0 0" up="0 1 0"/></transform></emitter>
    <emitter type="directional"><vector name="direction" x="0" y="-2" z="0"/><rgb name="irradiance" value="3"/></emitter>
    <emitter type="envmap"><string name="filename" value="sky.exr"/><float name="scale" value="4"/>
      <transform name="to_world"><rotate y="1" angle="90"/><translate x="100"/></transform></emitter>)");
  ASSERT_EQ(s.lights.size(), 4u);
  EXPECT_EQ(s.lights[0].type, LIGHT_POINT);
  EXPECT_FLOAT_EQ(s.lights[0].position[2], 3.0f);
  EXPECT_FLOAT_EQ(s.lights[0].radiance[1], 10.0f);
  const GdrLight& spot = s.lights[1];
  EXPECT_NEAR(spot.direction[2], -1.0f, 1e-6);
  EXPECT_NEAR(spot.cos_cutoff, std::cos(20 * M_PI / 180), 1e-6);
  EXPECT_NEAR(spot.cos_falloff, std::cos(15 * M_PI / 180), 1e-6);
  const GdrLight& sun = s.lights[2];
  EXPECT_FLOAT_EQ(sun.direction[1], -1.0f);
  EXPECT_NEAR(sun.scene_radius, std::sqrt(3.0f), 1e-5);  // the [-1,1]^3 cube
  const GdrLight& envl = s.lights[3];
  EXPECT_EQ(envl.type, LIGHT_ENVMAP);
  ASSERT_GE(envl.texture, 0);
  EXPECT_EQ(s.textures[envl.texture].width, 4);
  EXPECT_FLOAT_EQ(s.texels[s.textures[envl.texture].offset].y, 2.0f);  // EXR: linear, no decoding
  EXPECT_FLOAT_EQ(envl.radiance[0], 4.0f);
  EXPECT_FLOAT_EQ(envl.to_world[3], 0.0f);  // translation dropped
  EXPECT_NEAR(envl.to_world[2], 1.0f, 1e-6);  // rotation about y by 90: z -> x
  EXPECT_NEAR(envl.to_local[8], 1.0f, 1e-6);  // and back: x -> z
  const SceneFeatures& f = s.features;
  EXPECT_TRUE(f.delta_lights);
  EXPECT_TRUE(f.environment);
  std::map<std::string, std::string> d = f.kernel_defines();
  for (const char* name : {"GDR_LIGHT_POINT", "GDR_LIGHT_SPOT", "GDR_LIGHT_DIRECTIONAL", "GDR_LIGHT_ENVMAP"})
    EXPECT_EQ(d.count(name), 1u) << name;
  EXPECT_EQ(d.count("GDR_LIGHT_AREA"), 0u);
}

TEST(SceneEmitters, ConstantEnvironment) {
  test::TempFolder folder;
  Scene s = load_body(folder, R"(<shape type="cube"/>
    <emitter type="constant"><rgb name="radiance" value="0.5"/></emitter>)");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, LIGHT_CONSTANT);
  EXPECT_FLOAT_EQ(s.lights[0].radiance[2], 0.5f);
  EXPECT_TRUE(s.features.environment);
  EXPECT_EQ(s.features.kernel_defines().count("GDR_LIGHT_CONSTANT"), 1u);
}

TEST(SceneEmitters, SecondEnvironmentIsAnError) {
  test::TempFolder folder;
  try {
    load_body(folder, R"(<shape type="cube"/>
    <emitter type="constant"/>
    <emitter type="constant"/>)");
    FAIL() << "two environment emitters must not load";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("second environment emitter"), std::string::npos) << e.what();
    EXPECT_GT(e.line(), 0);
  }
}

TEST(SceneSensor, FovAxesFocalLengthAndFilters) {
  test::TempFolder folder;
  auto camera = [&](const std::string& inner) {
    return load_scene(folder.write("c.xml", test::scene_xml("<sensor type=\"perspective\">" + inner +
                                                            "<film type=\"hdrfilm\"><integer name=\"width\" value=\"400\"/>"
                                                            "<integer name=\"height\" value=\"200\"/>"
                                                            "<rfilter type=\"gaussian\"><float name=\"stddev\" value=\"0.25\"/></rfilter>"
                                                            "</film></sensor>")))
        .camera;
  };
  double t = std::tan(M_PI / 8);  // fov 45
  GdrCamera smaller = camera(R"(<float name="fov" value="45"/><string name="fov_axis" value="smaller"/>)");
  EXPECT_NEAR(smaller.tan_half_fov_y, t, 1e-6);
  EXPECT_NEAR(smaller.tan_half_fov_x, 2 * t, 1e-6);
  GdrCamera larger = camera(R"(<float name="fov" value="45"/><string name="fov_axis" value="larger"/>)");
  EXPECT_NEAR(larger.tan_half_fov_x, t, 1e-6);
  GdrCamera diag = camera(R"(<float name="fov" value="45"/><string name="fov_axis" value="diagonal"/>)");
  EXPECT_NEAR(std::hypot(diag.tan_half_fov_x, diag.tan_half_fov_y), t, 1e-6);
  EXPECT_NEAR(diag.tan_half_fov_x / diag.tan_half_fov_y, 2.0, 1e-6);
  EXPECT_EQ(diag.filter, FILTER_GAUSSIAN);
  EXPECT_FLOAT_EQ(diag.filter_radius, 1.0f);  // 4 standard deviations
  // 50 mm on 35 mm film: the diagonal (43.27 mm) spans 2 atan(43.27 / 100).
  GdrCamera lens = camera(R"(<string name="focal_length" value="50mm"/>)");
  EXPECT_NEAR(std::hypot(lens.tan_half_fov_x, lens.tan_half_fov_y), std::sqrt(36.0 * 36 + 24 * 24) / 100, 1e-6);
  // Neither fov nor focal_length: Mitsuba's 50 mm (not a 45 degree fov).
  GdrCamera plain = camera("");
  EXPECT_FLOAT_EQ(plain.tan_half_fov_x, lens.tan_half_fov_x);
  EXPECT_FLOAT_EQ(plain.tan_half_fov_y, lens.tan_half_fov_y);
  EXPECT_THROW(camera(R"(<float name="fov" value="45"/><string name="fov_axis" value="sideways"/>)"), InputError);
}

TEST(SceneDescribe, SummaryNamesSizesFeaturesAndWarnings) {
  test::TempFolder folder;
  Scene s = load_body(folder, R"(<integrator type="path"><integer name="max_depth" value="5"/></integrator>
    <shape type="sphere" id="ball"><bsdf type="dielectric" id="glass"/>
      <emitter type="area"><rgb name="radiance" value="1"/></emitter></shape>
    <shape type="cube"><bsdf type="hair"/></shape>)");
  std::string d = describe_scene(s);
  EXPECT_NE(d.find("shapes: 2"), std::string::npos) << d;
  EXPECT_NE(d.find("resolution: 768x576"), std::string::npos) << d;
  EXPECT_NE(d.find("max_depth: 5"), std::string::npos) << d;
  EXPECT_NE(d.find("area triangles"), std::string::npos) << d;
  EXPECT_NE(d.find("specular chains: on (1 delta material: glass (dielectric))"), std::string::npos) << d;
  EXPECT_NE(d.find("hair"), std::string::npos) << d;
  EXPECT_NE(d.find("film filter: gaussian (radius 2 px), sample_border: off"), std::string::npos) << d;
  EXPECT_EQ(d.find("coating tables"), std::string::npos) << d;
}

TEST(SceneDescribe, SaysWhichFilmAndCoatingTablesTheSceneUses) {
  test::TempFolder folder;
  Scene s = load_scene(folder.write("s.xml", test::scene_xml(R"(<sensor type="perspective"><film type="hdrfilm">
      <boolean name="sample_border" value="true"/><rfilter type="box"/></film></sensor>
    <shape type="sphere"><bsdf type="roughplastic"/></shape>)")));
  std::string d = describe_scene(s);
  EXPECT_NE(d.find("film filter: box (radius 0.5 px), sample_border: on"), std::string::npos) << d;
  EXPECT_NE(d.find("coating tables: on (plastic: the coating's internal reflectance, and roughplastic's"),
            std::string::npos) << d;
}

}  // namespace
}  // namespace gdr
