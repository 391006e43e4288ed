// The loaded scene: flat arrays in the layouts of kernels/shared/scene_types.h, ready to upload,
// plus what the host needs on its own (names, the features the scene calls for).
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include "scene/scene_features.h"
#include "shared/scene_types.h"

namespace gdr {

struct Vec4 {
  float x = 0, y = 0, z = 0, w = 0;
};

struct Scene {
  std::string path;  // the top-level scene file

  // Geometry: every shape is triangles.
  std::vector<Vec4> positions;  // world space, w unused
  std::vector<Vec4> normals;    // per vertex (same count as positions), world space; zero for
                                // shapes without SHAPE_HAS_NORMALS (kernels use the geometric one)
  std::vector<float> uvs;       // two per vertex (zero without SHAPE_HAS_UVS)
  std::vector<GdrTriangle> triangles;
  std::vector<GdrShape> shapes;
  std::vector<std::string> shape_names;  // id or "<type> at FILE:LINE", for messages

  std::vector<GdrMaterial> materials;
  std::vector<std::string> material_names;
  std::vector<GdrTexture> textures;
  std::vector<Vec4> texels;  // linear RGB
  std::vector<GdrLight> lights;

  GdrCamera camera{};
  int spp = 16;             // the scene's sampler sample_count
  std::string integrator;   // the scene's integrator type ("path", ...), empty if none
  std::string integrator_file;  // where the <integrator> element is, for messages
  int integrator_line = 0;
  int max_depth = -1;       // the integrator's max_depth (-1: unbounded in Mitsuba)
  // Mitsuba 3's scene property embree_use_robust_intersections: Embree's robust mode, watertight
  // at edges and vertices at some cost in traversal speed (off, as in Mitsuba 3).
  bool robust_intersections = false;

  SceneFeatures features;
  std::vector<std::string> warnings;  // unsupported features, each naming element, file and line

  // Bounding box of the geometry (world space).
  float bounds_min[3] = {0, 0, 0};
  float bounds_max[3] = {0, 0, 0};

  // Radius of the bounding box's bounding sphere (0 for an empty or point-sized scene).
  double bounding_radius() const {
    double d2 = 0;
    for (int i = 0; i < 3; ++i) {
      double d = double(bounds_max[i]) - double(bounds_min[i]);
      d2 += d * d;
    }
    return 0.5 * std::sqrt(d2);
  }
};

}  // namespace gdr
