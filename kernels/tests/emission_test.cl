// Emission sampling for the host tests (kernels/light/emission.h): the host draws the seeds and
// does the statistics; every value comes from the kernels.
#include "core/rng.h"
#include "light/emission.h"

// Emission of light `index` sampled with the engine's RNG keyed by (seed, pixel 0, sample i):
// pos[i] = (p, pdf_pos), dir[i] = (dir, pdf_dir), le[i] = (le, sampled (1) or not (0)),
// check[i] = (n, the direction pdf light_emission_pdf_dir gives of the sampled direction, with
// light_emission_pdf_pos's position pdf in the last slot of pos when they are compared).
__kernel void emission_sample_rng(SCENE_DATA_ARGS, int light_count, int env, int index, uint seed, uint n,
                                  __global float4* pos, __global float4* dir, __global float4* le,
                                  __global float4* check) {
  uint i = get_global_id(0);
  if (i >= n) return;
  SceneData s = scene_data_make(SCENE_DATA_NAMES, light_count, env);
  float4 u = rng_block(seed, 0u, i, 0u);
  EmissionSample e;
  int ok = light_emission_sample_index(&s, index, u.xy, u.zw, &e);
  pos[i] = (float4)(e.p, e.pdf_pos);
  dir[i] = (float4)(e.dir, e.pdf_dir);
  le[i] = (float4)(e.le, ok ? 1.0f : 0.0f);
  float area = 0.0f;
  if (s.lights[index].type == LIGHT_AREA) area = 1.0f / e.pdf_pos;
  check[i] = (float4)(e.delta_dir ? 1.0f : light_emission_pdf_dir(&s, index, e.n, e.dir),
                      light_emission_pdf_pos(&s, index, area), e.pmf, 0.0f);
}

// pdf[i] = light_emission_pdf_dir of light `index` (normal `normal`) for direction dir[i].
__kernel void emission_pdf_dir(SCENE_DATA_ARGS, int light_count, int env, int index, float4 normal, uint n,
                               __global const float4* dir, __global float* pdf) {
  uint i = get_global_id(0);
  if (i >= n) return;
  SceneData s = scene_data_make(SCENE_DATA_NAMES, light_count, env);
  pdf[i] = light_emission_pdf_dir(&s, index, normal.xyz, dir[i].xyz);
}
