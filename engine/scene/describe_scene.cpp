#include "scene/describe_scene.h"

#include <sstream>

namespace gdr {

std::string describe_scene(const Scene& scene) {
  std::ostringstream out;
  out << "scene: " << scene.path << "\n";
  out << "shapes: " << scene.shapes.size() << ", triangles: " << scene.triangles.size()
      << ", vertices: " << scene.positions.size() << "\n";
  out << "materials: " << scene.materials.size() << ", textures: " << scene.textures.size()
      << " (" << scene.texels.size() << " texels)\n";
  int counts[LIGHT_TYPE_COUNT] = {};
  for (const GdrLight& l : scene.lights)
    if (l.type >= 0 && l.type < LIGHT_TYPE_COUNT) ++counts[l.type];
  out << "lights: " << scene.lights.size();
  bool first = true;
  for (int t = 0; t < LIGHT_TYPE_COUNT; ++t) {
    if (!counts[t]) continue;
    out << (first ? " (" : ", ") << counts[t] << " " << light_type_name(t) << (t == LIGHT_AREA ? " triangles" : "");
    first = false;
  }
  out << (first ? "" : ")") << "\n";
  out << "resolution: " << scene.camera.width << "x" << scene.camera.height << ", spp: " << scene.spp << "\n";
  static const char* const kFilters[] = {"box", "tent", "gaussian"};
  const GdrCamera& cam = scene.camera;
  out << "film filter: " << (cam.filter >= 0 && cam.filter < 3 ? kFilters[cam.filter] : "unknown") << " (radius "
      << cam.filter_radius << " px), sample_border: "
      << (cam.sample_border ? "on (the filter's support past the image is sampled)" : "off (samples inside the image)")
      << "\n";
  out << "integrator: " << (scene.integrator.empty() ? "(none given)" : scene.integrator)
      << ", max_depth: " << scene.max_depth << (scene.max_depth < 0 ? " (unbounded)" : "") << "\n";
  out << "bounds: (" << scene.bounds_min[0] << ", " << scene.bounds_min[1] << ", " << scene.bounds_min[2] << ") - ("
      << scene.bounds_max[0] << ", " << scene.bounds_max[1] << ", " << scene.bounds_max[2] << ")\n";
  out << scene.features.describe();
  if (scene.warnings.empty()) {
    out << "warnings: none\n";
  } else {
    out << "warnings: " << scene.warnings.size() << "\n";
    for (const std::string& w : scene.warnings) out << "  " << w << "\n";
  }
  return out.str();
}

}  // namespace gdr
