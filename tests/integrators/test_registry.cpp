// The integrator registry: every entry builds and renders a tiny scene to a finite, lit image
// (gradient entries with their primal and gradient layers); names and scene types resolve; an
// unknown name is an error that lists the names; the command line lists them and rejects others.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "cli/cli_harness.h"
#include "integrators/registry.h"
#include "scene/load_scene.h"
#include "support/render.h"
#include "util/error.h"

namespace gdr {
namespace {

Scene tiny_cornell_box() {
  LoadOptions o;
  o.defines = {{"res", "8"}};
  return load_scene(test::source_scene("cornell-box.xml"), o);
}

TEST(Registry, EveryEntryRendersATinyScene) {
  Scene scene = tiny_cornell_box();
  test::SceneOnDevice on_device(scene);
  ASSERT_FALSE(integrator_registry().empty());
  for (const IntegratorEntry& e : integrator_registry()) {
    SCOPED_TRACE(e.name);
    EXPECT_FALSE(e.description.empty());
    std::unique_ptr<Integrator> integrator = e.make(on_device.inputs(), IntegratorParams{});
    RenderSettings s;
    s.spp = 2;
    s.seed = 3;
    RenderResult r = integrator->render(s);
    EXPECT_EQ(r.samples, 2);
    ASSERT_EQ(r.image.width, 8);
    ASSERT_EQ(r.image.height, 8);
    std::vector<float> rgb = r.image.rgb_layer("");
    double sum = 0;
    for (float v : rgb) {
      ASSERT_TRUE(std::isfinite(v));
      sum += v;
    }
    EXPECT_GT(sum, 0.0);
    for (const char* layer : {"primal", "dx", "dy"}) EXPECT_EQ(r.image.has_rgb_layer(layer), e.gradient) << layer;
  }
}

TEST(Registry, EveryEntryWritesAuxLayersWhenAsked) {
  Scene scene = tiny_cornell_box();
  test::SceneOnDevice on_device(scene);
  for (const IntegratorEntry& e : integrator_registry()) {
    if (std::find(e.params.begin(), e.params.end(), "aux") == e.params.end()) continue;
    SCOPED_TRACE(e.name);
    IntegratorParams p;
    p.set("aux", "true");
    RenderSettings s;
    s.spp = 1;
    RenderResult r = e.make(on_device.inputs(), p)->render(s);
    for (const char* layer : {"albedo", "normal", "depth"}) {
      ASSERT_TRUE(r.image.has_rgb_layer(layer)) << layer;
      double sum = 0;
      for (float v : r.image.rgb_layer(layer)) sum += std::fabs(v);
      EXPECT_GT(sum, 0.0) << layer;
    }
  }
}

TEST(Registry, NamesAndSceneTypesResolve) {
  EXPECT_EQ(find_integrator("pt").name, "pt");
  EXPECT_EQ(find_integrator("gpt").name, "gpt");
  EXPECT_TRUE(find_integrator("gpt").gradient);
  ASSERT_NE(integrator_for_scene_type("path"), nullptr);
  EXPECT_EQ(integrator_for_scene_type("path")->name, "pt");
  EXPECT_EQ(integrator_for_scene_type("no-such-type"), nullptr);
}

TEST(Registry, UnknownNameListsTheNames) {
  try {
    find_integrator("no-such-integrator");
    FAIL() << "no error";
  } catch (const Error& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("no-such-integrator"), std::string::npos) << msg;
    for (const IntegratorEntry& entry : integrator_registry()) EXPECT_NE(msg.find(entry.name), std::string::npos) << msg;
  }
}

TEST(Registry, BadParameterValueIsAnErrorNamingIt) {
  Scene scene = tiny_cornell_box();
  test::SceneOnDevice on_device(scene);
  IntegratorParams p;
  p.set("strategy", "sideways");
  try {
    find_integrator("pt").make(on_device.inputs(), p);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("strategy"), std::string::npos) << e.what();
  }
}

TEST(Registry, CommandLineListsAndChecksIntegrators) {
  test::TempDir dir;
  test::CliResult list = test::run_gdrender("--list-integrators", dir);
  ASSERT_EQ(list.code, 0) << list.output;
  test::CliResult help = test::run_gdrender("--help", dir);
  ASSERT_EQ(help.code, 0) << help.output;
  for (const IntegratorEntry& e : integrator_registry()) {
    EXPECT_NE(list.output.find("  " + e.name), std::string::npos) << list.output;
    EXPECT_NE(list.output.find(e.description), std::string::npos) << list.output;
    EXPECT_NE(help.output.find(e.description), std::string::npos) << help.output;
  }
  std::string scene = "'" + test::source_scene("cornell-box.xml") + "'";
  test::CliResult bad = test::run_gdrender(scene + " --integrator bogus -D res=8 --spp 1 -o out.exr", dir);
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.output.find("unknown integrator 'bogus'"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find(integrator_names()), std::string::npos) << bad.output;
}

// A scene asking for an integrator gdrender lacks renders with pt and says so, naming the
// element's file and line; with --strict it is an error.
TEST(Registry, UnknownSceneIntegratorIsAWarningOrAnError) {
  test::TempDir dir;
  std::ofstream(dir.file("volpath.xml")) << R"(<scene version="3.0.0">
  <integrator type="volpath"/>
  <shape type="sphere"><emitter type="area"><rgb name="radiance" value="1"/></emitter></shape>
  <sensor type="perspective"><film type="hdrfilm"><integer name="width" value="4"/><integer name="height" value="4"/></film></sensor>
</scene>)";
  test::CliResult r = test::run_gdrender("volpath.xml --spp 1 -o out.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("volpath.xml:2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("volpath"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("rendering with pt"), std::string::npos) << r.output;
  test::CliResult strict = test::run_gdrender("volpath.xml --spp 1 --strict -o strict.exr", dir);
  EXPECT_NE(strict.code, 0) << strict.output;
  EXPECT_NE(strict.output.find("volpath.xml:2"), std::string::npos) << strict.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("strict.exr")));
}

// A parameter the chosen integrator does not read is named.
TEST(Registry, UnreadParameterIsNamed) {
  test::TempDir dir;
  std::string scene = "'" + test::source_scene("cornell-box.xml") + "'";
  test::CliResult r = test::run_gdrender(scene + " --integrator pt --shift replay -D res=8 --spp 1 -o out.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("--shift does not apply to pt"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace gdr
