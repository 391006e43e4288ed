// Eight paths a work item (--lanes 8, a CPU device's default). pt_generate_lanes writes the
// camera rays, queue and path states pt_generate writes, bit for bit: the gaussian filter's lanes
// do the scalar operations, and the other filters and the pixels the image cuts go through the
// scalar sampler (odd film sizes and a pixel count that is no multiple of 8, so the last work
// item is partial). The diffuse queue shaded eight paths a work item (pt_shade_lanes_diffuse)
// makes the decisions pt_shade_diffuse makes, path by path: the same light samples
// accepted, the same continuations and roulette, so Embree traces as many bounce and shadow
// rays. The directions differ only by the cosine-weighted sample's sine and cosine, a polynomial
// within 4e-7 of PoCL's sinpi and cospi. In the Cornell box (one material type: the queue
// unrouted, misses shaded in the kernel) and the environment scene (routed by pt_route_lanes
// against pt_route, an environment map, two-sided diffuse beside other types) the ray counts are
// equal and the images' relative L1 difference below 1e-6 (measured 2.8e-8 and 1.0e-8). Behind
// the glass box's dielectric a refraction can turn that difference into another path: counts
// within 1e-3 (measured 6e-5), images within 1e-4 (measured 5.5e-6). A two-sided diffuse
// rectangle seen from behind, lit by a point light and a constant environment (a delta light's
// unweighted samples, the back side's flip): equal counts, images within 1e-6. The same for the
// smooth plastic queue (its lanes: pt_shade_lanes_plastic). Deterministic (seed 9, 4 spp, 64 px
// films).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <utility>
#include <vector>
#include <string>

#include "accel/embree_scene.h"
#include "image/image_io.h"
#include "integrators/pt/path_tracer.h"
#include "render/device_scene.h"
#include "scene/load_scene.h"
#include "support/agreement.h"
#include "scene/scene_test_files.h"
#include "support/render.h"
#include "util/error.h"

namespace gdr {
namespace {

struct LanesRender {
  Image image;
  uint64_t bounce_rays = 0, shadow_rays = 0, lane_items = 0, scalar_items = 0;
};

LanesRender render_with(const Scene& scene, int lanes) {
  Stats stats;
  test::SceneOnCountingDevice on_device(scene, &stats);
  RenderSettings s;
  s.spp = 4;
  s.seed = 9;
  s.max_depth = 8;
  PtSettings pt;
  pt.lanes = lanes;
  LanesRender r;
  r.image = PathTracer(on_device.inputs(), pt).render(s).image;
  r.bounce_rays = stats.count("rays/bounce");
  r.shadow_rays = stats.count("rays/shadow");
  for (const char* type : {"diffuse", "plastic"}) {
    r.lane_items += stats.count(std::string("kernel_items/pt_shade_lanes_") + type);
    r.scalar_items += stats.count(std::string("kernel_items/pt_shade_") + type);
  }
  return r;
}

void expect_lanes_match(const Scene& scene, const std::string& file, double ray_tolerance, double image_tolerance) {
  LanesRender one = render_with(scene, 1), eight = render_with(scene, 8);
  EXPECT_EQ(one.lane_items, 0u) << file;
  EXPECT_EQ(eight.scalar_items, 0u) << file;
  EXPECT_GT(eight.lane_items, 0u) << file;
  EXPECT_GT(one.shadow_rays, 0u) << file;
  // Entries shaded, bounce rays, shadow rays.
  for (auto [a, b] : {std::pair{eight.lane_items, one.scalar_items}, std::pair{eight.bounce_rays, one.bounce_rays},
                      std::pair{eight.shadow_rays, one.shadow_rays}}) {
    EXPECT_LE(std::abs(double(a) - double(b)), ray_tolerance * double(b)) << file << ": " << a << " against " << b;
  }
  ASSERT_EQ(eight.image.pixels.size(), one.image.pixels.size());
  double diff = 0.0, sum = 0.0;
  for (size_t i = 0; i < one.image.pixels.size(); ++i) {
    ASSERT_TRUE(std::isfinite(eight.image.pixels[i])) << file << ": value " << i;
    diff += std::abs(double(eight.image.pixels[i]) - double(one.image.pixels[i]));
    sum += std::abs(double(one.image.pixels[i]));
  }
  ASSERT_GT(sum, 0.0) << file;
  EXPECT_LT(diff / sum, image_tolerance) << file;
  std::printf("%s: relative L1 difference %.3g\n", file.c_str(), diff / sum);
}

void expect_project_scene_matches(const std::string& file, double ray_tolerance, double image_tolerance) {
  Scene scene = test::project_scene(file, 64);
  expect_lanes_match(scene, file, ray_tolerance, image_tolerance);
}

TEST(ShadingLanes, CornellBoxShadesAsOnePathAWorkItem) { expect_project_scene_matches("cornell-box.xml", 0.0, 1e-6); }
TEST(ShadingLanes, EnvironmentSceneShadesAsOnePathAWorkItem) {
  expect_project_scene_matches("environment.xml", 0.0, 1e-6);
}
TEST(ShadingLanes, GlassBoxShadesAsOnePathAWorkItem) { expect_project_scene_matches("glass-box.xml", 1e-3, 1e-4); }

TEST(ShadingLanes, TwoSidedBackAndPointLightShadeAsOnePathAWorkItem) {
  test::TempFolder folder;
  const std::string file = folder.write("back.xml", test::scene_xml(R"(
    <sensor type="perspective"><float name="fov" value="60"/>
      <transform name="to_world"><lookat origin="0, 0, 4" target="0, 0, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="64"/><integer name="height" value="64"/></film>
    </sensor>
    <shape type="rectangle">
      <bsdf type="twosided"><bsdf type="diffuse"><rgb name="reflectance" value="0.6, 0.5, 0.4"/></bsdf></bsdf>
      <transform name="to_world"><rotate y="1" angle="180"/></transform>
    </shape>
    <shape type="cube"><bsdf type="diffuse"/>
      <transform name="to_world"><scale value="0.3"/><translate x="0.5" y="0.4" z="1"/></transform>
    </shape>
    <emitter type="point"><point name="position" x="0" y="1" z="3"/><rgb name="intensity" value="10"/></emitter>
    <emitter type="constant"><rgb name="radiance" value="0.2"/></emitter>)"));
  Scene scene = load_scene(file);
  ASSERT_EQ(scene.materials.size(), 2u);
  ASSERT_TRUE(scene.materials[scene.shapes[0].material].twosided);
  expect_lanes_match(scene, "two-sided back", 0.0, 1e-6);
}

// Smooth plastic (one-sided, two-sided seen from behind, with a nonlinear, textured base) beside
// diffuse, under an environment map and a point light: the plastic queue's lanes pick the coating's
// reflection or the base as the scalar kernel does (both lobes, both delta and rough continuations).
TEST(ShadingLanes, PlasticShadesAsOnePathAWorkItem) {
  test::TempFolder folder;
  Image sky(16, 8, {"R", "G", "B"});
  for (size_t i = 0; i < sky.pixels.size(); ++i) sky.pixels[i] = i % 29 == 0 ? 30.0f : 0.3f + 0.05f * float(i % 5);
  write_exr(folder.path("sky.exr"), sky);
  const std::string file = folder.write("plastic.xml", test::scene_xml(R"(
    <sensor type="perspective"><float name="fov" value="50"/>
      <transform name="to_world"><lookat origin="0, 1, 5" target="0, 0.6, 0" up="0, 1, 0"/></transform>
      <film type="hdrfilm"><integer name="width" value="64"/><integer name="height" value="48"/></film>
    </sensor>
    <emitter type="envmap"><string name="filename" value="sky.exr"/></emitter>
    <emitter type="point"><point name="position" x="1" y="3" z="2"/><rgb name="intensity" value="6"/></emitter>
    <shape type="sphere"><point name="center" x="-1.1" y="1" z="0"/><float name="radius" value="1"/>
      <bsdf type="plastic">
        <rgb name="diffuse_reflectance" value="0.9, 0.3, 0.3"/><float name="int_ior" value="1.9"/>
      </bsdf>
    </shape>
    <shape type="sphere"><point name="center" x="1.1" y="1" z="0"/><float name="radius" value="1"/>
      <bsdf type="plastic"><boolean name="nonlinear" value="true"/>
        <texture type="checkerboard" name="diffuse_reflectance">
          <rgb name="color0" value="0.8"/><rgb name="color1" value="0.1, 0.4, 0.7"/>
        </texture>
      </bsdf>
    </shape>
    <shape type="rectangle">
      <bsdf type="twosided"><bsdf type="plastic"><rgb name="diffuse_reflectance" value="0.5"/></bsdf></bsdf>
      <transform name="to_world"><scale value="0.6"/><rotate y="1" angle="180"/><translate y="2.3" z="1"/></transform>
    </shape>
    <shape type="rectangle"><bsdf type="diffuse"/>
      <transform name="to_world"><scale value="5"/><rotate x="1" angle="-90"/></transform>
    </shape>)"));
  Scene scene = load_scene(file);
  ASSERT_EQ(scene.materials.size(), 4u);
  expect_lanes_match(scene, "plastic", 0.0, 1e-6);
}

// The camera queue of the first pass (all pixels, sample 0) with `lanes` paths a work item.
struct CameraQueue {
  std::vector<GdrRayHit> rays;
  std::vector<cl_uint> slots;
  std::vector<GdrPathState> paths;
};

CameraQueue generate_with(const Scene& scene, int lanes) {
  Context& ctx = test::default_context();
  EmbreeScene embree(scene, BuildQuality::High);
  DeviceScene device_scene(ctx, scene);
  PtSettings pt;
  pt.batches = 1;
  pt.lanes = lanes;
  PathTracer tracer(RenderInputs{ctx, scene, embree, device_scene}, pt);
  RenderSettings settings;
  settings.seed = 5;
  settings.max_depth = scene.max_depth;
  const uint32_t pixels = uint32_t(scene.camera.width) * uint32_t(scene.camera.height);
  tracer.generate(tracer.params(settings, 3, 0, pixels));
  CameraQueue q{tracer.rays(0).read(), tracer.queue(0).read(), tracer.paths().read()};
  q.rays.resize(pixels);
  q.slots.resize(pixels);
  q.paths.resize(pixels);
  return q;
}

TEST(ShadingLanes, CameraRaysAreOnePathAWorkItems) {
  Scene base = load_scene(test::source_scene("cornell-box.xml"));
  for (int filter : {FILTER_GAUSSIAN, FILTER_TENT, FILTER_BOX}) {
    for (int border : {0, 1}) {
      Scene scene = base;
      scene.camera.width = 37;
      scene.camera.height = 23;
      scene.camera.filter = filter;
      // Mitsuba's defaults: wide enough that the image cuts its border pixels' filters.
      scene.camera.filter_radius = filter == FILTER_GAUSSIAN ? 2.0f : filter == FILTER_TENT ? 1.0f : 0.5f;
      scene.camera.sample_border = border;
      const CameraQueue one = generate_with(scene, 1), eight = generate_with(scene, 8);
      const std::string what = "filter " + std::to_string(filter) + ", border " + std::to_string(border);
      ASSERT_EQ(one.rays.size(), eight.rays.size()) << what;
      size_t differ = 0;  // the rays (write_ray_hit leaves the hit's other fields to the intersection)
      for (size_t i = 0; i < one.rays.size(); ++i) {
        differ += std::memcmp(&one.rays[i].ray, &eight.rays[i].ray, sizeof(GdrRay)) != 0 ||
                  one.rays[i].hit.geomID != eight.rays[i].hit.geomID;
      }
      EXPECT_EQ(differ, 0u) << what << ": of " << one.rays.size();
      EXPECT_EQ(one.slots, eight.slots) << what;
      EXPECT_EQ(std::memcmp(one.paths.data(), eight.paths.data(), one.paths.size() * sizeof(GdrPathState)), 0)
          << what;
    }
  }
}

TEST(ShadingLanes, ParameterIsChecked) {
  using Values = std::map<std::string, std::string>;
  EXPECT_EQ(pt_settings(IntegratorParams(Values{{"lanes", "8"}})).lanes, 8);
  EXPECT_EQ(pt_settings(IntegratorParams(Values{{"lanes", "1"}})).lanes, 1);
  EXPECT_FALSE(pt_settings(IntegratorParams{}).lanes.has_value());
  EXPECT_THROW(pt_settings(IntegratorParams(Values{{"lanes", "4"}})), Error);
}

}  // namespace
}  // namespace gdr
