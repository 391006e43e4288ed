// A scene build (the kernels hold only the BSDF, light and texture code the scene uses: the
// default, what gdrender renders with) and an all-type build (Context::scene_kernels off, what the
// rest of the suite renders with) render the same image, bit for bit: the types a scene lacks are
// code its build leaves out, never a change to what the rest computes. The path tracer on the
// project's Cornell box (diffuse, area light), glass box (diffuse, dielectric) and environment
// scene (diffuse, rough conductor, rough plastic, environment map, textures); G-PT on the
// environment scene. 32 px, 2 spp, seed 9, max depth 6.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "integrators/gpt/gradient_path_tracer.h"
#include "render/wavefront/kernel_factory.h"
#include "scene/scene_features.h"
#include "support/agreement.h"
#include "support/render.h"
#include "util/error.h"

namespace gdr {
namespace {

RenderSettings short_render() {
  RenderSettings s;
  s.spp = 2;
  s.seed = 9;
  s.max_depth = 6;
  return s;
}

// A render's inputs on a context of its own that builds the scene's kernels or every type's.
struct OnBuild {
  OnBuild(const Scene& scene, bool scene_kernels) : on_device(scene, &stats, scene_kernels) {}
  Stats stats;
  test::SceneOnCountingDevice on_device;
};

// The two builds differ: the all-type program holds the shading kernel of a type the scene lacks.
void expect_builds_differ(const Scene& scene, OnBuild& own, OnBuild& all, const std::string& file) {
  for (int t = 0; t < BSDF_TYPE_COUNT; ++t) {
    if (scene.features.bsdf[t]) continue;
    const std::string name = std::string("pt_shade_") + bsdf_type_name(t);
    EXPECT_THROW(KernelFactory(own.on_device.context, scene).make("pt/pt.cl", name), Error) << file << ": " << name;
    EXPECT_NO_THROW(KernelFactory(all.on_device.context, scene).make("pt/pt.cl", name)) << file << ": " << name;
    return;
  }
  ADD_FAILURE() << file << " has every BSDF type";
}

void expect_pt_builds_agree(const std::string& file) {
  const Scene scene = test::project_scene(file, 32);
  OnBuild own(scene, true), all(scene, false);
  const std::vector<float> a = PathTracer(own.on_device.inputs(), {}).render(short_render()).image.rgb_layer("");
  const std::vector<float> b = PathTracer(all.on_device.inputs(), {}).render(short_render()).image.rgb_layer("");
  expect_builds_differ(scene, own, all, file);
  EXPECT_GT(*std::max_element(a.begin(), a.end()), 0.0f) << file;
  EXPECT_EQ(a, b) << file;
}

TEST(SceneKernels, PathTracerCornellBox) { expect_pt_builds_agree("cornell-box.xml"); }
TEST(SceneKernels, PathTracerGlassBox) { expect_pt_builds_agree("glass-box.xml"); }
TEST(SceneKernels, PathTracerEnvironmentScene) { expect_pt_builds_agree("environment.xml"); }

TEST(SceneKernels, GptEnvironmentScene) {
  const Scene scene = test::project_scene("environment.xml", 32);
  OnBuild own(scene, true), all(scene, false);
  const GradientImages a = GradientPathTracer(own.on_device.inputs(), {}).render_gradients(short_render());
  const GradientImages b = GradientPathTracer(all.on_device.inputs(), {}).render_gradients(short_render());
  EXPECT_GT(*std::max_element(a.primal.begin(), a.primal.end()), 0.0f);
  EXPECT_EQ(a.primal, b.primal);
  EXPECT_EQ(a.dx, b.dx);
  EXPECT_EQ(a.dy, b.dy);
  EXPECT_EQ(a.direct, b.direct);
}

}  // namespace
}  // namespace gdr
