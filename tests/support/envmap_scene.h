// A scene lit by an environment map with a bright patch (importance sampled by luminance) over
// a dim sky, written to a temporary folder and loaded: a diffuse and a rough metal sphere on a
// plane, 32x24 pixels.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "image/image_io.h"
#include "scene/load_scene.h"

namespace gdr::test {

inline Scene envmap_scene() {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("gdr-envmap-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Image env(32, 16, {});
  std::vector<float> rgb(32 * 16 * 3, 0.2f);
  for (int y = 3; y < 6; ++y) {
    for (int x = 10; x < 13; ++x) {
      for (int c = 0; c < 3; ++c) rgb[3 * (y * 32 + x) + c] = 40.0f;
    }
  }
  env.add_rgb_layer("", rgb);
  write_exr((dir / "sky.exr").string(), env);
  std::ofstream(dir / "scene.xml") << R"(<scene version="3.0.0">
  <sensor type="perspective"><float name="fov" value="40"/>
    <transform name="to_world"><lookat origin="0, 1, 6" target="0, 0.5, 0" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="24"/></film>
  </sensor>
  <emitter type="envmap"><string name="filename" value="sky.exr"/>
    <transform name="to_world"><rotate y="1" angle="30"/></transform></emitter>
  <shape type="sphere"><point name="center" x="-1" y="1" z="0"/><float name="radius" value="1"/>
    <bsdf type="diffuse"/></shape>
  <shape type="sphere"><point name="center" x="1.2" y="1" z="0"/><float name="radius" value="1"/>
    <bsdf type="roughconductor"><float name="alpha" value="0.3"/></bsdf></shape>
  <shape type="rectangle"><transform name="to_world"><scale value="5"/><rotate x="1" angle="-90"/></transform>
    <bsdf type="diffuse"/></shape>
</scene>)";
  Scene scene = load_scene((dir / "scene.xml").string());
  fs::remove_all(dir);
  return scene;
}

}  // namespace gdr::test
