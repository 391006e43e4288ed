// The project's own scenes (scenes/*.xml) load without a single warning, with what they are
// meant to exercise.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/describe_scene.h"
#include "scene/load_scene.h"
#include "support/source_scene.h"

namespace gdr {
namespace {

Scene load_project_scene(const std::string& name) { return load_scene(test::source_scene(name)); }

class ProjectScene : public testing::TestWithParam<const char*> {};

TEST_P(ProjectScene, LoadsWithoutWarnings) {
  Scene s = load_project_scene(GetParam());
  EXPECT_TRUE(s.warnings.empty()) << describe_scene(s);
  EXPECT_GT(s.triangles.size(), 0u);
  EXPECT_GT(s.lights.size(), 0u);
  EXPECT_EQ(s.integrator, "path");
  EXPECT_EQ(s.spp, 64);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ProjectScene,
                         testing::Values("cornell-box.xml", "cornell-box-caustics.xml", "glossy-plates.xml",
                                         "glass-box.xml", "glossy-glass-box.xml", "environment.xml"));

TEST(ProjectScenes, CornellBoxIsDiffuseWithAreaLight) {
  Scene s = load_project_scene("cornell-box.xml");
  EXPECT_EQ(s.camera.width, 256);
  EXPECT_EQ(s.camera.height, 256);
  EXPECT_EQ(s.max_depth, 8);
  // Camera at (278, 273, -800) looking along +z.
  EXPECT_FLOAT_EQ(s.camera.to_world[3], 278.0f);
  EXPECT_FLOAT_EQ(s.camera.to_world[7], 273.0f);
  EXPECT_FLOAT_EQ(s.camera.to_world[11], -800.0f);
  EXPECT_NEAR(s.camera.to_world[10], 1.0f, 1e-6);
  EXPECT_NEAR(s.camera.tan_half_fov_x, std::tan(39.3 / 2 * M_PI / 180), 1e-6);
  // Floor, ceiling, back, 2 walls, light (1 quad each) and two blocks (5 quads each).
  EXPECT_EQ(s.shapes.size(), 8u);
  EXPECT_EQ(s.triangles.size(), 2u * (6 + 10));
  EXPECT_EQ(s.lights.size(), 2u);  // the light quad's two triangles
  const SceneFeatures& f = s.features;
  EXPECT_TRUE(f.bsdf[BSDF_DIFFUSE]);
  for (int t = 1; t < BSDF_TYPE_COUNT; ++t) EXPECT_FALSE(f.bsdf[t]) << bsdf_type_name(t);
  EXPECT_TRUE(f.light[LIGHT_AREA]);
  for (int t = 1; t < LIGHT_TYPE_COUNT; ++t) EXPECT_FALSE(f.light[t]) << light_type_name(t);
  EXPECT_FALSE(f.specular_chains());
  EXPECT_FALSE(f.textures);
  EXPECT_FALSE(f.environment);
  EXPECT_FALSE(f.delta_lights);
  std::map<std::string, std::string> defines = f.kernel_defines();
  EXPECT_EQ(defines.size(), 2u);
  EXPECT_EQ(defines.count("GDR_BSDF_DIFFUSE"), 1u);
  EXPECT_EQ(defines.count("GDR_LIGHT_AREA"), 1u);
}

TEST(ProjectScenes, CornellBoxDefaultsCanBeOverridden) {
  LoadOptions options;
  options.defines = {{"res", "64"}, {"spp", "4"}, {"max_depth", "3"}};
  Scene s = load_scene(test::source_scene("cornell-box.xml"), options);
  EXPECT_EQ(s.camera.width, 64);
  EXPECT_EQ(s.spp, 4);
  EXPECT_EQ(s.max_depth, 3);
}

TEST(ProjectScenes, CausticsSceneHasSpecularChains) {
  Scene s = load_project_scene("cornell-box-caustics.xml");
  const SceneFeatures& f = s.features;
  EXPECT_TRUE(f.bsdf[BSDF_CONDUCTOR]);
  EXPECT_TRUE(f.bsdf[BSDF_DIELECTRIC]);
  EXPECT_TRUE(f.delta_surfaces);
  EXPECT_TRUE(f.specular_chains());
  EXPECT_NE(f.describe().find("specular chains: on"), std::string::npos) << f.describe();
  EXPECT_NE(f.describe().find("glass"), std::string::npos) << f.describe();
}

TEST(ProjectScenes, GlossyPlatesAreNearDeltaOnlyBelowThreshold) {
  LoadOptions options;
  options.glossy_threshold = 0.01f;  // the smoothest plate has alpha 0.005
  Scene s = load_scene(test::source_scene("glossy-plates.xml"), options);
  EXPECT_TRUE(s.features.near_delta_surfaces);
  EXPECT_FALSE(s.features.delta_surfaces);
  options.glossy_threshold = 0.001f;
  s = load_scene(test::source_scene("glossy-plates.xml"), options);
  EXPECT_FALSE(s.features.specular_chains());
}

// The two glass boxes share the room, the camera and the slabs (scenes/fragments/glass-box-*.xml)
// and differ in the sphere alone: diffuse in one, glossy plastic in the other.
TEST(ProjectScenes, GlassBoxesDifferInTheSphereAlone) {
  Scene diffuse = load_project_scene("glass-box.xml");
  Scene glossy = load_project_scene("glossy-glass-box.xml");
  EXPECT_EQ(diffuse.triangles.size(), glossy.triangles.size());
  EXPECT_EQ(diffuse.lights.size(), glossy.lights.size());
  EXPECT_EQ(diffuse.camera.width, glossy.camera.width);
  EXPECT_TRUE(diffuse.features.specular_chains());
  EXPECT_TRUE(glossy.features.specular_chains());
  EXPECT_FALSE(diffuse.features.bsdf[BSDF_ROUGH_PLASTIC]);
  EXPECT_TRUE(glossy.features.bsdf[BSDF_ROUGH_PLASTIC]);
  for (int t = 0; t < BSDF_TYPE_COUNT; ++t) {
    if (t != BSDF_ROUGH_PLASTIC) EXPECT_EQ(diffuse.features.bsdf[t], glossy.features.bsdf[t]) << bsdf_type_name(t);
  }
}

TEST(ProjectScenes, EnvironmentSceneHasDistantLights) {
  Scene s = load_project_scene("environment.xml");
  EXPECT_TRUE(s.features.environment);
  EXPECT_TRUE(s.features.delta_lights);
  for (const GdrLight& l : s.lights) {
    if (l.type == LIGHT_DIRECTIONAL || l.type == LIGHT_CONSTANT) {
      EXPECT_GT(l.scene_radius, 20.0f);  // the 40 x 40 ground plane
    }
  }
}

}  // namespace
}  // namespace gdr
