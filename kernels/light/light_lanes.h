// Light samples for kernels that shade several lanes (pt/shade_lanes.h): light_sample lane by
// lane, except that an environment map's steps go over all the lanes that chose it before the next
// step (its draw: EnvDraw, light/envmap.h; then its pdf, its texels), so that the lanes' table
// reads overlap where one lane's reads would wait one after another.
#pragma once
#include "core/lanes.h"
#include "light/lights.h"

// light_sample for each lane k with want[k]: the light chosen by u0[k], a point on it by
// (u1[k], u2[k]), seen from lane k of p. ok[k]: whether ls[k] holds a sample.
inline void light_sample_lanes(const SceneData* s, const int* want, const float* u0, const float* u1,
                               const float* u2, const LaneArray3* p, int* ok, LightSample* ls) {
  int env[LANES];
  for (int k = 0; k < LANES; ++k) {
    ok[k] = env[k] = 0;
    if (!want[k]) continue;
    int light = light_select(s, u0[k]);
#if defined(GDR_LIGHT_ENVMAP)
    if (s->lights[light].type == LIGHT_ENVMAP) {
      env[k] = 1;  // drawn below
      continue;
    }
#endif
    ok[k] = light_sample(s, light, lane_array3_get(p, k), (float2)(u1[k], u2[k]), &ls[k]);
  }
#if defined(GDR_LIGHT_ENVMAP)
  if (s->env_light < 0 || s->lights[s->env_light].type != LIGHT_ENVMAP) return;
  __global const GdrLight* l = &s->lights[s->env_light];
  __global const GdrTexture* t = &s->textures[l->texture];
  __global const float* table = s->env_tables + l->distribution_offset;
  int w = t->width, h = t->height;
  float pmf = light_pmf(s, s->env_light);
  EnvDraw d[LANES];
  for (int k = 0; k < LANES; ++k) {
    if (env[k]) d[k] = envmap_draw_row(table, h, (float2)(u1[k], u2[k]));
  }
  for (int k = 0; k < LANES; ++k) {
    if (env[k]) envmap_draw_column(table, w, h, &d[k]);
  }
  float2 uv[LANES];
  for (int k = 0; k < LANES; ++k) {
    if (env[k]) uv[k] = envmap_draw_uv(table, w, h, &d[k]);
  }
  float p_uv[LANES];
  LaneArray3 texel;
  for (int k = 0; k < LANES; ++k) {
    if (env[k]) p_uv[k] = envmap_uv_pdf(table, w, h, uv[k]);
  }
  for (int k = 0; k < LANES; ++k) {
    if (env[k]) lane_array3_set(&texel, k, envmap_lookup(s, t, uv[k]));
  }
  for (int k = 0; k < LANES; ++k) {
    if (!env[k]) continue;
    ls[k].wi = envmap_sample_at(l, pmf, uv[k], p_uv[k], lane_array3_get(&texel, k), &ls[k].radiance, &ls[k].pdf);
    ok[k] = environment_sample_done(&ls[k]);
  }
#endif
}
