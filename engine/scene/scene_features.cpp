#include "scene/scene_features.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "scene/layout_checks.h"
#include "scene/scene.h"
#include "shared/material_class.h"

namespace gdr {
namespace {

const char* const kBsdfNames[BSDF_TYPE_COUNT] = {"diffuse",        "conductor",       "roughconductor",
                                                  "dielectric",     "thindielectric",  "roughdielectric",
                                                  "plastic",        "roughplastic"};
const char* const kBsdfDefines[BSDF_TYPE_COUNT] = {"DIFFUSE",         "CONDUCTOR",        "ROUGH_CONDUCTOR",
                                                    "DIELECTRIC",      "THIN_DIELECTRIC",  "ROUGH_DIELECTRIC",
                                                    "PLASTIC",         "ROUGH_PLASTIC"};
const char* const kLightNames[LIGHT_TYPE_COUNT] = {"area", "point", "spot", "directional", "constant", "envmap"};
const char* const kLightDefines[LIGHT_TYPE_COUNT] = {"AREA", "POINT", "SPOT", "DIRECTIONAL", "CONSTANT", "ENVMAP"};

// The kernels' classification (kernels/shared/material_class.h), as bsdf_from_material() sees the
// material: delta lobes, and the roughness the shifts compare with the glossy threshold.
bool has_delta_lobe(const GdrMaterial& m) { return material_has_delta_lobe(m.type, m.eta[0]); }
float roughness(const GdrMaterial& m) {
  return material_roughness(m.type, m.eta[0], material_alpha(m.alpha_u), material_alpha(m.alpha_v));
}
// A microfacet lobe smooth enough that the shifts treat it as specular.
bool near_delta(const GdrMaterial& m, float threshold) {
  return !has_delta_lobe(m) && m.type != BSDF_DIFFUSE &&
         !material_is_diffuse(roughness(m), threshold);
}

// "3 materials: a, b, c" listing at most four names.
std::string list_names(const std::vector<std::string>& names) {
  std::string s;
  for (size_t i = 0; i < names.size() && i < 4; ++i) s += (i ? ", " : "") + names[i];
  if (names.size() > 4) s += ", ...";
  return s;
}

}  // namespace

const char* bsdf_type_name(int type) {
  return type >= 0 && type < BSDF_TYPE_COUNT ? kBsdfNames[type] : "unknown";
}

const char* light_type_name(int type) {
  return type >= 0 && type < LIGHT_TYPE_COUNT ? kLightNames[type] : "unknown";
}

SceneFeatures compute_scene_features(const Scene& scene, float glossy_threshold) {
  SceneFeatures f;
  // Only materials that some shape uses count.
  std::vector<bool> used(scene.materials.size(), false);
  for (const GdrShape& s : scene.shapes)
    if (s.material >= 0 && static_cast<size_t>(s.material) < used.size()) used[s.material] = true;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (!used[i]) continue;
    const GdrMaterial& m = scene.materials[i];
    if (m.type < 0 || m.type >= BSDF_TYPE_COUNT) continue;
    f.bsdf[m.type] = true;
    if (has_delta_lobe(m)) f.delta_surfaces = true;
    if (near_delta(m, glossy_threshold)) f.near_delta_surfaces = true;
    if (m.reflectance_texture >= 0) f.textures = true;
  }
  for (const GdrLight& l : scene.lights) {
    if (l.type < 0 || l.type >= LIGHT_TYPE_COUNT) continue;
    f.light[l.type] = true;
    if (l.type == LIGHT_POINT || l.type == LIGHT_SPOT || l.type == LIGHT_DIRECTIONAL) f.delta_lights = true;
    if (l.type == LIGHT_CONSTANT || l.type == LIGHT_ENVMAP) f.environment = true;
  }
  f.glossy_threshold = glossy_threshold;
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (!used[i]) continue;
    const GdrMaterial& m = scene.materials[i];
    std::string name = i < scene.material_names.size() ? scene.material_names[i] : std::to_string(i);
    if (has_delta_lobe(m)) f.delta_materials.push_back(name + " (" + bsdf_type_name(m.type) + ")");
    if (near_delta(m, glossy_threshold)) {
      std::ostringstream s;
      s << name << " (" << bsdf_type_name(m.type) << ", alpha " << roughness(m) << ")";
      f.near_delta_materials.push_back(s.str());
    }
  }
  return f;
}

std::map<std::string, std::string> SceneFeatures::kernel_defines() const {
  std::map<std::string, std::string> d;
  for (int i = 0; i < BSDF_TYPE_COUNT; ++i)
    if (bsdf[i]) d["GDR_BSDF_" + std::string(kBsdfDefines[i])] = "1";
  for (int i = 0; i < LIGHT_TYPE_COUNT; ++i)
    if (light[i]) d["GDR_LIGHT_" + std::string(kLightDefines[i])] = "1";
  if (textures) d["GDR_TEXTURES"] = "1";
  return d;
}

std::string SceneFeatures::describe() const {
  std::ostringstream out;
  std::vector<std::string> bsdfs, lights;
  for (int i = 0; i < BSDF_TYPE_COUNT; ++i)
    if (bsdf[i]) bsdfs.push_back(kBsdfNames[i]);
  for (int i = 0; i < LIGHT_TYPE_COUNT; ++i)
    if (light[i]) lights.push_back(kLightNames[i]);
  out << "BSDFs: " << (bsdfs.empty() ? "none" : list_names(bsdfs)) << "\n";
  out << "lights: " << (lights.empty() ? "none" : list_names(lights)) << "\n";
  if (textures) out << "textures: on (bitmap/checkerboard reflectance)\n";
  if (bsdf[BSDF_PLASTIC] || bsdf[BSDF_ROUGH_PLASTIC]) {
    out << "coating tables: on (plastic: the coating's internal reflectance"
        << (bsdf[BSDF_ROUGH_PLASTIC] ? ", and roughplastic's external transmittance," : "")
        << " tabulated per material by a kernel at upload)\n";
  }
  if (specular_chains()) {
    out << "specular chains: on (";
    if (delta_surfaces) {
      out << delta_materials.size() << " delta material" << (delta_materials.size() == 1 ? "" : "s") << ": "
          << list_names(delta_materials);
    }
    if (near_delta_surfaces) {
      out << (delta_surfaces ? "; " : "") << near_delta_materials.size() << " near-delta material"
          << (near_delta_materials.size() == 1 ? "" : "s") << " (alpha < " << glossy_threshold
          << "): " << list_names(near_delta_materials);
    }
    out << ")\n";
  } else {
    out << "specular chains: off (no delta or near-delta surfaces)\n";
  }
  if (delta_lights) out << "delta lights: on (point, spot or directional emitters)\n";
  if (environment) out << "environment: on (" << (light[LIGHT_ENVMAP] ? "envmap" : "constant") << " emitter)\n";
  return out.str();
}

}  // namespace gdr
