// Helpers shared by the G-PT kernels (gpt.cl): pixel offsets of the four neighbours, the scene
// view, film accumulators, offset bookkeeping.
#pragma once
#include "bsdf/bsdf.h"
#include "core/ray_queue.h"
#include "scene/surface.h"
#include "shared/gpt_types.h"

#define OFFSET_PIXEL_DX(k) ((k) == GPT_DIR_PX ? 1 : (k) == GPT_DIR_NX ? -1 : 0)
#define OFFSET_PIXEL_DY(k) ((k) == GPT_DIR_PY ? 1 : (k) == GPT_DIR_NY ? -1 : 0)

inline SceneData gpt_scene(const GdrGptParams* p, SCENE_DATA_ARGS) {
  return scene_data_make(SCENE_DATA_NAMES, p->path.light_count, p->path.env_light);
}

// Accumulators are indexed by pixel over the whole image, so gpt_gather can read neighbours.
inline void acc_add(__global float4* acc, uint pixel, int slot, float3 c) {
  if (c.x != 0.0f || c.y != 0.0f || c.z != 0.0f) acc[pixel * GPT_ACC_COUNT + slot] += (float4)(c, 0.0f);
}

inline void kill_offset(GptOffsetState* o, __global uint* counters, int reason) {
  o->mode = GPT_MODE_DEAD;
  atomic_inc(&counters[reason]);
}

inline int offset_alive(const GptOffsetState* o) { return o->mode != GPT_MODE_DEAD; }

// A contribution that is not finite is dropped and counted (never reaches a film).
inline float3 checked(float3 c, __global uint* counters) {
  if (is_finite3(c)) return c;
  atomic_inc(&counters[GPT_COUNTER_NONFINITE]);
  return (float3)(0.0f);
}

inline Bsdf surface_bsdf(const SceneData* s, const Surface* su) {
  return bsdf_from_material(&s->materials[su->material], surface_reflectance(s, su));
}

inline int is_diffuse(const Bsdf* b, float threshold) { return bsdf_roughness(b) > threshold; }
