// Scenes lit by an environment map made in code, written to a temporary folder and loaded.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "scene/load_scene.h"

namespace gdr::test {

// Loads scene `xml`, which names the environment map (w x h grey texels) "sky.exr".
inline Scene scene_with_environment(int w, int h, const std::vector<float>& grey, const std::string& xml) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("gdr-envmap-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Image env(w, h, {});
  std::vector<float> rgb;
  for (float v : grey) rgb.insert(rgb.end(), 3, v);
  env.add_rgb_layer("", rgb);
  write_exr((dir / "sky.exr").string(), env);
  std::ofstream(dir / "scene.xml") << xml;
  Scene scene = load_scene((dir / "scene.xml").string());
  fs::remove_all(dir);
  return scene;
}

// Two unit spheres on a 10 x 10 plane seen from (0, 1, 6), 32x24 pixels, lit by `emitter` (its
// XML); the left sphere and the plane diffuse, the right sphere `right_bsdf` (XML).
inline std::string spheres_on_plane_xml(const std::string& emitter, const std::string& right_bsdf) {
  return R"(<scene version="3.0.0">
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 1, 6" target="0, 0.5, 0" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/></film>
  </sensor>
  )" + emitter + R"(
  <shape type="sphere"><point name="center" x="-1" y="1" z="0"/><float name="radius" value="1"/>
    <bsdf type="diffuse"/></shape>
  <shape type="sphere"><point name="center" x="1.2" y="1" z="0"/><float name="radius" value="1"/>
    )" + right_bsdf + R"(</shape>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/><rotate x="1" angle="-90"/></transform>
    <bsdf type="diffuse"/></shape>
</scene>)";
}

// A bright patch (importance sampled by luminance) over a dim sky: a diffuse and a rough metal
// sphere on a plane, 32x24 pixels.
inline Scene envmap_scene() {
  std::vector<float> sky(32 * 16, 0.2f);
  for (int y = 3; y < 6; ++y) {
    for (int x = 10; x < 13; ++x) sky[y * 32 + x] = 40.0f;
  }
  return scene_with_environment(
      32, 16, sky,
      spheres_on_plane_xml(R"(<emitter type="envmap"><string name="filename" value="sky.exr"/>
    <transform name="to_world"><rotate y="1" angle="30"/></transform></emitter>)",
                           R"(<bsdf type="roughconductor"><float name="alpha" value="0.3"/></bsdf>)"));
}

// A smooth plastic sphere filling the frame (24x18 pixels) under a sky of scattered bright
// texels (27% of a 64x32 map, fixed seed): neighbouring pixels' BSDF samples of the plastic's
// diffuse lobe leave toward texels of unrelated brightness, so the sky's sampling pdf differs
// between the two paths of a pair.
inline Scene plastic_sphere_scene() {
  std::mt19937 rng(7);
  std::bernoulli_distribution bright(0.27);
  std::vector<float> sky(64 * 32);
  for (float& v : sky) v = bright(rng) ? 4.0f : 0.01f;
  return scene_with_environment(64, 32, sky, R"(<scene version="3.0.0">
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 1.6, 3.2" target="0, 0.9, 0" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="24"/><integer name="height" value="18"/></film>
  </sensor>
  <emitter type="envmap"><string name="filename" value="sky.exr"/>
    <transform name="to_world"><rotate y="1" angle="60"/></transform></emitter>
  <shape type="sphere"><point name="center" x="0" y="1" z="0"/><float name="radius" value="1"/>
    <bsdf type="plastic"/></shape>
</scene>)");
}

}  // namespace gdr::test
