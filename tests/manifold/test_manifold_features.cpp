// The manifold shift costs nothing where a scene has no specular chains: none of its kernels is
// compiled into G-PT's program and none is launched, so --shift manifold renders as the hybrid
// shift. Where the scene has chains, the walks run and are counted.
#include <gtest/gtest.h>

#include "integrators/gpt/gradient_path_tracer.h"
#include "scene/load_scene.h"
#include "support/render.h"
#include "support/source_scene.h"

namespace gdr {
namespace {

// Every stats entry whose name mentions the manifold stage.
std::vector<std::string> manifold_entries(const nlohmann::json& j, const std::string& prefix = "") {
  std::vector<std::string> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    std::string name = prefix + it.key();
    if (it->is_object()) {
      for (const std::string& s : manifold_entries(*it, name + "/")) out.push_back(s);
    } else if (name.find("manifold") != std::string::npos && name.find("settings/") != 0) {
      out.push_back(name);
    }
  }
  return out;
}

nlohmann::json render_manifold(const std::string& file) {
  Stats stats;
  Context context(select_device(""), &stats);
  Scene scene = load_scene(test::source_scene(file));
  scene.camera.width = scene.camera.height = 32;
  test::SceneOnDevice on_device(scene, &stats, context);
  GptSettings gs;
  gs.shift = GPT_SHIFT_MANIFOLD;
  GradientPathTracer gpt(on_device.inputs(), gs);
  RenderSettings s;
  s.spp = 4;
  gpt.render_gradients(s);
  return stats.to_json();
}

TEST(ManifoldFeatures, DiffuseSceneCompilesAndLaunchesNothingOfIt) {
  Scene scene = load_scene(test::source_scene("cornell-box.xml"));
  GptSettings gs;
  gs.shift = GPT_SHIFT_MANIFOLD;
  EXPECT_FALSE(gpt_manifold_enabled(scene, gs));
  // G-PT's program as this scene builds it has no manifold kernel.
  KernelFactory kernels(test::default_context(), scene);
  EXPECT_THROW(kernels.make("gpt/gpt.cl", "manifold_propose"), Error);
  EXPECT_THROW(kernels.make("gpt/gpt.cl", "gpt_manifold_join"), Error);
  std::vector<std::string> entries = manifold_entries(render_manifold("cornell-box.xml"));
  EXPECT_TRUE(entries.empty()) << "first: " << (entries.empty() ? "" : entries[0]);
}

TEST(ManifoldFeatures, SceneWithSpecularChainsWalks) {
  nlohmann::json j = render_manifold("cornell-box-caustics.xml");
  EXPECT_GT(j["counters"]["manifold"]["walks"].get<double>(), 0.0);
  EXPECT_GT(j["counters"]["manifold"]["solved"].get<double>(), 0.0);
  EXPECT_GT(j["counters"]["shifts"]["manifold"].get<double>(), 0.0);
}

}  // namespace
}  // namespace gdr
