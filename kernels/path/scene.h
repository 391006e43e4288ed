// What the path stages read of the scene: the scene view of a launch, and a surface's BSDF.
#pragma once
#include "bsdf/bsdf.h"
#include "scene/surface.h"
#include "shared/pt_types.h"

inline SceneData path_scene(const GdrPtParams* p, SCENE_DATA_ARGS) {
  return scene_data_make(SCENE_DATA_NAMES, p->light_count, p->env_light);
}

inline Bsdf surface_bsdf(const SceneData* s, const Surface* su) {
  return bsdf_from_material(&s->materials[su->material], s->coating_tables, surface_reflectance(s, su));
}
