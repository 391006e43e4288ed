// Emission a path finds by BSDF sampling: what the environment sends along an escaped ray and
// what an area light sends from a surface it hits, each with the pdf light sampling would have
// had of the same point; and the path tracer's MIS weight of such emission for its strategies.
#pragma once
#include "light/lights.h"
#include "path/mis.h"
#include "shared/pt_types.h"

// Radiance arriving along -dir at a path that escaped along dir.
inline float3 escaped_radiance(const SceneData* s, float3 dir) {
  return environment_radiance(s, &s->lights[s->env_light], dir);
}

inline float escaped_light_pdf(const SceneData* s, float3 dir) { return environment_pdf(s, dir); }

// Radiance the area light of su (su->light >= 0) sends toward wo.
inline float3 surface_radiance(const SceneData* s, const Surface* su, float3 wo) {
  return area_radiance(s, su->light, su->ng, wo);
}

// Solid-angle pdf of light sampling for the point of su seen at distance dist from direction wo.
inline float surface_light_pdf(const SceneData* s, const Surface* su, float dist, float3 wo) {
  return area_pdf(s, su->light, su->area, dist, dot(su->ng, wo));
}

// Whether emission found by BSDF sampling takes weight 1: seen from the camera, through a delta
// vertex, or under BSDF sampling alone.
inline int emission_unweighted(const GdrPathState* st, int strategy) {
  return st->depth == 0 || (st->flags & PATH_FLAG_SPECULAR) || strategy == PT_STRATEGY_BSDF;
}

// MIS weight of emission found by BSDF sampling, against light sampling with pdf `light_pdf`.
inline float emission_weight(const GdrPathState* st, int strategy, float light_pdf) {
  if (emission_unweighted(st, strategy)) return 1.0f;
  if (strategy == PT_STRATEGY_LIGHT) return 0.0f;
  return power_heuristic(st->bsdf_pdf, light_pdf);
}

// The weighted contribution of the environment to a path (throughput beta) escaping along dir.
inline float3 path_escaped_emission(const SceneData* s, const GdrPathState* st, float3 beta, float3 dir,
                                    int strategy) {
  float light_pdf;
  float3 le = environment_eval(s, dir, &light_pdf);
  return beta * le * emission_weight(st, strategy, light_pdf);
}

// The weighted contribution *c of the surface a path hit at distance dist (from direction wo);
// 0 where it emits nothing.
inline int path_surface_emission(const SceneData* s, const GdrPathState* st, float3 beta, const Surface* su,
                                 float3 wo, float dist, int strategy, float3* c) {
  if (su->light < 0) return 0;
  float3 le = surface_radiance(s, su, wo);
  if (!(le.x > 0.0f || le.y > 0.0f || le.z > 0.0f)) return 0;
  float light_pdf = surface_light_pdf(s, su, dist, wo);
  *c = beta * le * emission_weight(st, strategy, light_pdf);
  return 1;
}
