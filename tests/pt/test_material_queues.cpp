// The path tracer's per-material queues: a scene pays only for the materials it has. Its program
// holds a shading kernel for each BSDF type the scene uses and none for the others, a render
// launches exactly those (counted per kernel in the stats), and every routed hit is shaded by
// one of them. On the project's diffuse Cornell box (one type: no routing), the glass box
// (diffuse and dielectric) and the environment scene (diffuse, rough conductor, rough plastic),
// with the diffuse queue shaded one path and eight paths a work item (pt_shade_lanes_diffuse; the
// smooth plastic queue too, pt_shade_lanes_plastic, where a scene has one; routed by pt_route or
// pt_route_lanes).
// The images do not depend on the routing: scripts/render-hashes renders them bit for bit as one
// shading kernel did.
#include <gtest/gtest.h>

#include <string>

#include "integrators/pt/path_tracer.h"
#include "render/wavefront/kernel_factory.h"
#include "scene/scene_features.h"
#include "support/agreement.h"
#include "support/render.h"
#include "util/error.h"

namespace gdr {
namespace {

// The kernel that shades type t's queue.
std::string shade_kernel(int t, int lanes) {
  const bool laned = lanes == 8 && (t == BSDF_DIFFUSE || t == BSDF_PLASTIC);
  return std::string(laned ? "pt_shade_lanes_" : "pt_shade_") + bsdf_type_name(t);
}

void expect_queues_of(const std::string& file, int expected_types, int lanes) {
  Scene scene = test::project_scene(file, 32);
  Stats stats;
  test::SceneOnCountingDevice on_device(scene, &stats, true);  // what this suite checks: the scene's own build
  RenderSettings s;
  s.spp = 2;
  s.seed = 9;
  s.max_depth = 6;
  PtSettings pt;
  pt.lanes = lanes;
  PathTracer(on_device.inputs(), pt).render(s);

  KernelFactory kernels(on_device.context, scene);
  int types = 0;
  uint64_t shaded = 0;
  for (int t = 0; t < BSDF_TYPE_COUNT; ++t) {
    const std::string name = shade_kernel(t, lanes), other = shade_kernel(t, lanes == 8 ? 1 : 8);
    if (name != other) EXPECT_EQ(stats.count("kernel_items/" + other), 0u) << file << ": " << other << " ran";
    if (scene.features.bsdf[t]) {
      ++types;
      EXPECT_GT(stats.count("kernel_items/" + name), 0u) << file << ": " << name << " never ran";
      shaded += stats.count("kernel_items/" + name);
    } else {
      EXPECT_EQ(stats.count("kernel_items/" + name), 0u) << file << ": " << name << " ran";
      EXPECT_THROW(kernels.make("pt/pt.cl", name), Error) << file << ": the program holds " << name;
    }
  }
  EXPECT_EQ(types, expected_types) << file;
  // Every queue entry was routed; the hits among them were shaded once each (misses are not).
  EXPECT_GT(shaded, 0u);
  const uint64_t routed = stats.count(lanes == 8 ? "kernel_items/pt_route_lanes" : "kernel_items/pt_route");
  EXPECT_EQ(stats.count(lanes == 8 ? "kernel_items/pt_route" : "kernel_items/pt_route_lanes"), 0u) << file;
  if (types > 1) {
    EXPECT_LE(shaded, routed) << file;
  } else {
    EXPECT_EQ(routed + stats.count("kernel_items/keys_flags"), 0u)
        << file << ": routing where there is nothing to route";
  }
}

TEST(MaterialQueues, DiffuseOnlySceneLaunchesOnlyDiffuse) {
  for (int lanes : {1, 8}) expect_queues_of("cornell-box.xml", 1, lanes);
}
TEST(MaterialQueues, GlassBoxLaunchesItsTwoMaterials) {
  for (int lanes : {1, 8}) expect_queues_of("glass-box.xml", 2, lanes);
}
TEST(MaterialQueues, EnvironmentSceneLaunchesItsThreeMaterials) {
  for (int lanes : {1, 8}) expect_queues_of("environment.xml", 3, lanes);
}

}  // namespace
}  // namespace gdr
