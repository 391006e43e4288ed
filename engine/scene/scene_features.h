// What a scene calls for: decides what the kernels are compiled with (-D defines) and which
// kernels and machinery are launched, so a scene only pays for the effects it has.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "shared/material_class.h"
#include "shared/scene_types.h"

namespace gdr {

struct Scene;

struct SceneFeatures {
  bool bsdf[BSDF_TYPE_COUNT] = {};    // which BSDF types occur
  bool light[LIGHT_TYPE_COUNT] = {};  // which emitter types occur
  bool textures = false;              // a material reflectance is a bitmap or checkerboard texture
  bool delta_surfaces = false;        // smooth conductor/dielectric/plastic: specular (S) vertices
  bool near_delta_surfaces = false;   // rough BSDFs with alpha below the glossy threshold
  bool delta_lights = false;          // point, spot or directional lights
  bool environment = false;           // constant or envmap emitter

  // The reasons, for describe(): "name (type)" of the materials that make the surfaces delta or
  // near-delta, and the threshold used.
  std::vector<std::string> delta_materials;
  std::vector<std::string> near_delta_materials;
  float glossy_threshold = GDR_GLOSSY_THRESHOLD;

  // Specular chains (caustics, S-D-S paths) are possible: enables the manifold machinery.
  bool specular_chains() const { return delta_surfaces || near_delta_surfaces; }

  // -D defines for the kernel build: GDR_BSDF_<TYPE>, GDR_LIGHT_<TYPE>, GDR_TEXTURES, ...
  std::map<std::string, std::string> kernel_defines() const;
  // One line per enabled effect, with the reason (for --info and the render log).
  std::string describe() const;
};

// Computes the features of a loaded scene. `glossy_threshold` is the roughness (alpha) below
// which a rough surface is treated as near-delta.
SceneFeatures compute_scene_features(const Scene& scene, float glossy_threshold = GDR_GLOSSY_THRESHOLD);

const char* bsdf_type_name(int type);
const char* light_type_name(int type);

}  // namespace gdr
