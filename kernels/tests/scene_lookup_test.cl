// Texture and environment-map lookups and environment sampling for the host tests: the host
// draws the inputs and does the statistics; every value comes from kernels/scene and
// kernels/light, read through the scene buffers as DeviceScene binds them.
#include "core/rng.h"
#include "light/lights.h"
#include "scene/texture.h"

// out[i] = texture `index` at uv[i].
__kernel void texture_lookup(SCENE_DATA_ARGS, int index, uint n, __global const float2* uv, __global float4* out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  SceneData s = scene_data_make(SCENE_DATA_NAMES, 0, -1);
  out[i] = (float4)(texture_eval(&s, index, uv[i]), 0.0f);
}

// out[i] = (radiance the environment light `env` sends along -dir[i], its pdf of sampling dir[i]).
__kernel void environment_lookup(SCENE_DATA_ARGS, int light_count, int env, uint n, __global const float4* dir,
                                 __global float4* out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  SceneData s = scene_data_make(SCENE_DATA_NAMES, light_count, env);
  out[i] = (float4)(environment_radiance(&s, &s.lights[env], dir[i].xyz), environment_pdf(&s, dir[i].xyz));
}

// out[i] = (a direction sampled toward the environment with the engine's RNG keyed by
// (seed, pixel 0, sample i), 0).
__kernel void environment_sample_rng(SCENE_DATA_ARGS, int light_count, int env, uint seed, uint n,
                                     __global float4* out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  SceneData s = scene_data_make(SCENE_DATA_NAMES, light_count, env);
  float4 u = rng_block(seed, 0u, i, 0u);
  float3 radiance;
  float pdf;
  out[i] = (float4)(environment_sample(&s, env, u.xy, &radiance, &pdf), 0.0f);
}

// out[i] = the lat-long position (u, v) of direction dir[i] (light/envmap.h).
__kernel void environment_uv(uint n, __global const float4* dir, __global float2* out) {
  uint i = get_global_id(0);
  if (i < n) out[i] = envmap_uv(dir[i].xyz);
}
