// Light samples and environment lookups for kernels that shade several lanes (pt/shade_lanes.h,
// pt/route_lanes.h): light_sample lane by lane, except that an environment map samples all the
// lanes that chose it together (light/envmap_lanes.h), as it looks up the lanes' escaped rays.
#pragma once
#include "core/lanes.h"
#include "light/envmap_lanes.h"
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
  float pmf = light_pmf(s, s->env_light);
  int8 on = vload8(0, env) != 0;
  float8 u, v, p_uv;
  Lanes3 texel, radiance, wi;
  envmap_sample_uv_lanes(s, t, table, on, vload8(0, u1), vload8(0, u2), &u, &v);
  envmap_lookup_pdf_lanes(s, t, on, u, v, &texel, &p_uv);
  float8 pdf;
  wi = envmap_sample_at_lanes(l, pmf, u, v, p_uv, texel, &radiance, &pdf);
  LaneArray3 wi_k, radiance_k;
  lanes3_store(wi, &wi_k);
  lanes3_store(radiance, &radiance_k);
  float pdf_k[LANES];
  vstore8(pdf, 0, pdf_k);
  for (int k = 0; k < LANES; ++k) {
    if (!env[k]) continue;
    ls[k].wi = lane_array3_get(&wi_k, k);
    ls[k].radiance = lane_array3_get(&radiance_k, k);
    ls[k].pdf = pdf_k[k];
    ok[k] = environment_sample_done(&ls[k]);
  }
#endif
}

#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
// environment_eval for each lane in `on` (the scene has an environment): the radiance arriving
// along -dir and *pdf.
inline Lanes3 environment_eval_lanes(const SceneData* s, int8 on, Lanes3 dir, float8* pdf) {
  __global const GdrLight* l = &s->lights[s->env_light];
  float pmf = light_pmf(s, s->env_light);
#if defined(GDR_LIGHT_ENVMAP)
  if (l->type == LIGHT_ENVMAP) return envmap_eval_lanes(s, l, pmf, on, dir, pdf);
#endif
  *pdf = (float8)(pmf * GDR_INV_4PI);
  float3 r = vload3(0, l->radiance);
  Lanes3 le = {(float8)(r.x), (float8)(r.y), (float8)(r.z)};
  return le;
}
#endif
