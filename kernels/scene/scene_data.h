// The scene's device buffers, gathered in one private struct so stage functions take one
// argument. Each kernel fills it from its arguments with scene_data_make().
#pragma once
#include "shared/scene_types.h"

typedef struct SceneData {
  __global const GdrTriangle* triangles;
  __global const float4* positions;
  __global const float4* normals;
  __global const float2* uvs;
  __global const GdrShape* shapes;
  __global const GdrMaterial* materials;
  __global const GdrTexture* textures;
  __global const float4* texels;
  __global const GdrLight* lights;
  __global const float* light_cdf;  // light_count + 1 entries, cdf[0] = 0, cdf[light_count] = 1
  __global const float* env_cdf;    // envmap sampling tables (engine/integrators/environment_distribution.h)
  int light_count;
  int env_light;  // index of the environment light, or -1
} SceneData;

// The argument list every scene-reading kernel declares, and the call that packs it.
#define SCENE_DATA_ARGS                                                                          \
  __global const GdrTriangle *triangles, __global const float4 *positions,                      \
      __global const float4 *normals, __global const float2 *uvs, __global const GdrShape *shapes, \
      __global const GdrMaterial *materials, __global const GdrTexture *textures,               \
      __global const float4 *texels, __global const GdrLight *lights, __global const float *light_cdf, \
      __global const float *env_cdf

// The same arguments by name, to pass them on.
#define SCENE_DATA_NAMES \
  triangles, positions, normals, uvs, shapes, materials, textures, texels, lights, light_cdf, env_cdf

inline SceneData scene_data_make(SCENE_DATA_ARGS, int light_count, int env_light) {
  SceneData s;
  s.triangles = triangles;
  s.positions = positions;
  s.normals = normals;
  s.uvs = uvs;
  s.shapes = shapes;
  s.materials = materials;
  s.textures = textures;
  s.texels = texels;
  s.lights = lights;
  s.light_cdf = light_cdf;
  s.env_cdf = env_cdf;
  s.light_count = light_count;
  s.env_light = env_light;
  return s;
}
