// A human-readable summary of a loaded scene, for `gdrender --info`.
#pragma once
#include <string>

#include "scene/scene.h"

namespace gdr {

// Size (shapes, triangles, vertices, materials, textures, lights by type), resolution, spp,
// integrator, max_depth, the features (SceneFeatures::describe) and the loader's warnings.
std::string describe_scene(const Scene& scene);

}  // namespace gdr
