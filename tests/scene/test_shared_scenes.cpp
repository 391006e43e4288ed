// Every Mitsuba scene under ../shared/scenes (real scenes written elsewhere) either loads or is
// rejected with an InputError naming the file; none crashes. Skipped where the folder is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/describe_scene.h"
#include "scene/load_scene.h"
#include "util/error.h"

namespace fs = std::filesystem;

namespace gdr {
namespace {

std::string shared_scenes() { return std::string(GDR_SOURCE_DIR) + "/../shared/scenes"; }

#define REQUIRE_SHARED()                                                                   \
  if (!fs::is_directory(shared_scenes())) GTEST_SKIP() << "no shared scenes at " << shared_scenes()

TEST(SharedScenes, EveryXmlLoadsOrFailsCleanly) {
  REQUIRE_SHARED();
  int loaded = 0, rejected = 0;
  for (const auto& entry : fs::recursive_directory_iterator(shared_scenes())) {
    if (entry.path().extension() != ".xml") continue;
    std::string path = entry.path().string();
    try {
      Scene s = load_scene(path);
      ++loaded;
      std::printf("LOADED %s: %zu triangles, %zu lights, %zu warnings\n", path.c_str(), s.triangles.size(),
                  s.lights.size(), s.warnings.size());
      for (const auto& w : s.warnings) std::printf("   warning: %s\n", w.c_str());
    } catch (const InputError& e) {
      ++rejected;
      std::printf("REJECTED %s: %s\n", path.c_str(), e.what());
      EXPECT_NE(std::string(e.what()).find(".xml"), std::string::npos) << e.what();
    }
  }
  EXPECT_GT(loaded, 0);
  std::printf("%d loaded, %d rejected\n", loaded, rejected);
}

Scene load_shared(const std::string& rel) { return load_scene(shared_scenes() + "/" + rel); }

bool has_material(const Scene& s, int type) {
  for (const GdrShape& shape : s.shapes)
    if (s.materials[shape.material].type == type) return true;
  return false;
}

TEST(SharedScenes, MitsubaCornellBoxVariants) {
  REQUIRE_SHARED();
  for (const char* name : {"cbox.xml", "cbox-rgb.xml", "cbox-spectral.xml"}) {
    Scene s = load_shared(std::string("mitsuba-data/scenes/cbox/") + name);
    EXPECT_TRUE(s.warnings.empty()) << name << ": " << s.warnings.front();
    EXPECT_EQ(s.shapes.size(), 8u) << name;
    EXPECT_EQ(s.camera.width, 256) << name;
    EXPECT_EQ(s.max_depth, 6) << name;
    ASSERT_EQ(s.shapes[0].first_light, 0) << name;  // the luminaire
    EXPECT_EQ(s.lights.size(), static_cast<size_t>(s.shapes[0].triangle_count)) << name;
    EXPECT_GT(s.lights[0].radiance[0], s.lights[0].radiance[2]) << name;  // warm light
    EXPECT_FALSE(s.features.specular_chains()) << name;
  }
  // The spectral white is nearly flat from 420 nm on: a near-neutral reflectance.
  Scene spectral = load_shared("mitsuba-data/scenes/cbox/cbox-spectral.xml");
  const GdrMaterial& white = spectral.materials[spectral.shapes[1].material];
  EXPECT_NEAR(white.reflectance[0], white.reflectance[1], 0.05);
  EXPECT_NEAR(white.reflectance[1], 0.73, 0.05);
}

// The spectral Cornell box's colours are Mitsuba 3's: mitsuba 3.9.1, scalar_rgb,
// mi.traverse(mi.load_file('cbox.xml'))['red.reflectance.value'] and so on, printed with 9
// significant digits; within 1 float ulp.
TEST(SharedScenes, SpectralCornellBoxColoursAreMitsubas) {
  REQUIRE_SHARED();
  auto expect_ulp = [](const float* c, const double (&ref)[3], const char* what) {
    for (int k = 0; k < 3; ++k) {
      double ulp = std::ldexp(1.0, std::ilogb(static_cast<float>(ref[k])) - 23);
      EXPECT_LE(std::abs(c[k] - ref[k]), ulp) << what << " " << k << ": " << c[k] << " vs Mitsuba " << ref[k];
    }
  };
  const double light[3] = {0.77636677, 0.779810011, 0.77602911}, white[3] = {0.735013008, 0.735624611, 0.736264348},
               green[3] = {0.0682825372, 0.397760183, 0.0862908736},
               red[3] = {0.491320044, 0.0492281057, 0.0509218983}, radiance[3] = {20.7108364, 10.8546343, 2.77115202};
  for (const char* name : {"cbox.xml", "cbox-spectral.xml"}) {
    SCOPED_TRACE(name);
    Scene s = load_shared(std::string("mitsuba-data/scenes/cbox/") + name);
    ASSERT_EQ(s.shapes.size(), 8u);
    // Shapes in file order: luminaire, floor, ceiling, back, green wall, red wall, two boxes.
    expect_ulp(s.materials[s.shapes[0].material].reflectance, light, "luminaire");
    for (int i : {1, 2, 3, 6, 7}) expect_ulp(s.materials[s.shapes[i].material].reflectance, white, "white");
    expect_ulp(s.materials[s.shapes[4].material].reflectance, green, "green");
    expect_ulp(s.materials[s.shapes[5].material].reflectance, red, "red");
    expect_ulp(s.lights[0].radiance, radiance, "radiance");
  }
}

TEST(SharedScenes, BulbSceneWithMissingMeshIsACleanError) {
  REQUIRE_SHARED();
  try {
    load_shared("cbox-with-bulb/scene.xml");
    FAIL() << "the scene refers to meshes/sphere.obj, which was never published";
  } catch (const InputError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("scene.xml:62"), std::string::npos) << msg;
    EXPECT_NE(msg.find("missing file 'meshes/sphere.obj'"), std::string::npos) << msg;
  }
  Scene s = load_shared("cbox-with-bulb/scene.nosphere.xml");
  EXPECT_TRUE(has_material(s, BSDF_ROUGH_DIELECTRIC));
  EXPECT_TRUE(has_material(s, BSDF_ROUGH_CONDUCTOR));
  EXPECT_EQ(s.camera.width, 512);
  EXPECT_EQ(s.spp, 128);
}

TEST(SharedScenes, MatpreviewWithSerializedEnvmapAndCheckerboard) {
  REQUIRE_SHARED();
  Scene s = load_shared("mitsuba-data/scenes/matpreview/matpreview.xml");
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  EXPECT_EQ(s.shapes.size(), 3u);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, LIGHT_ENVMAP);
  EXPECT_FLOAT_EQ(s.lights[0].radiance[0], 3.0f);
  EXPECT_TRUE(s.features.textures);
  EXPECT_TRUE(has_material(s, BSDF_PLASTIC));
  bool checker = false;
  for (const GdrTexture& t : s.textures) checker |= t.type == TEXTURE_CHECKERBOARD;
  EXPECT_TRUE(checker);
}

TEST(SharedScenes, DocsBsdfScenes) {
  REQUIRE_SHARED();
  const std::pair<const char*, int> cases[] = {
      {"bsdf_dielectric_glass.xml", BSDF_DIELECTRIC},     {"bsdf_thindielectric_glass.xml", BSDF_THIN_DIELECTRIC},
      {"bsdf_roughdielectric_glass.xml", BSDF_ROUGH_DIELECTRIC}, {"bsdf_conductor_aluminium.xml", BSDF_CONDUCTOR},
      {"bsdf_roughconductor_copper.xml", BSDF_ROUGH_CONDUCTOR},  {"bsdf_plastic_default.xml", BSDF_PLASTIC},
      {"bsdf_roughplastic_ggx.xml", BSDF_ROUGH_PLASTIC}};
  for (const auto& [file, type] : cases) {
    Scene s = load_shared(std::string("mitsuba-data/docs/scenes/") + file);
    EXPECT_TRUE(s.warnings.empty()) << file;
    EXPECT_TRUE(has_material(s, type)) << file << " lacks " << bsdf_type_name(type);
    EXPECT_TRUE(s.features.bsdf[type]) << file;
  }
  Scene bunny = load_shared("mitsuba-data/docs/scenes/shape_ply_bunny.xml");
  EXPECT_GT(bunny.triangles.size(), 69451u);  // the bunny's faces plus the plane
  EXPECT_EQ(bunny.materials[bunny.shapes[0].material].twosided, 1);
}

TEST(SharedScenes, VeachMisThroughAWrapper) {
  REQUIRE_SHARED();
  // veach_mis.xml is an include fragment whose meshes lie beside docs/scenes.
  std::string docs = shared_scenes() + "/mitsuba-data/docs/scenes";
  std::string wrapper = (fs::temp_directory_path() / "gdr_veach_wrapper.xml").string();
  {
    std::ofstream out(wrapper);
    out << "<scene version=\"3.0.0\"><path value=\"" << docs << "\"/><include filename=\"" << docs
        << "/include/veach_mis.xml\"/></scene>";
  }
  Scene s = load_scene(wrapper);
  fs::remove(wrapper);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
  int plates = 0;
  for (const GdrShape& shape : s.shapes) plates += s.materials[shape.material].type == BSDF_ROUGH_PLASTIC;
  EXPECT_EQ(plates, 4);
  int emitting_shapes = 0;
  for (const GdrShape& shape : s.shapes) emitting_shapes += shape.first_light >= 0;
  EXPECT_EQ(emitting_shapes, 5);
  EXPECT_EQ(s.camera.width, 768);
}

}  // namespace
}  // namespace gdr
