// Next-event estimation: the light and the point on it a path's vertex connects to, drawn from
// the light block of the path's random numbers, and the path tracer's MIS weight of the sample.
#pragma once
#include "core/frame.h"
#include "light/lights.h"
#include "path/mis.h"
#include "path/sides.h"
#include "sampling/path_sampler.h"
#include "shared/pt_types.h"

// A delta BSDF cannot be evaluated toward a light point.
inline int nee_applies(const SceneData* s, const Bsdf* b) { return s->light_count > 0 && !bsdf_is_delta(b); }

// Samples *light and a point on it (*ls) for the vertex su at `depth`, with the direction in su's
// shading frame. Returns 0 when there is no usable sample (also when the normals disagree on the
// side of the direction).
__attribute__((always_inline)) inline int nee_sample(const SceneData* s, const PathSampler* ps, int depth,
                                                     const Surface* su, const Frame* frame, int* light,
                                                     LightSample* ls, float3* wi_local) {
  float4 ul = sampler_block(ps, RNG_BLOCK_LIGHT(depth));
  *light = light_select(s, ul.x);
  if (!light_sample(s, *light, su->p, ul.yz, ls)) return 0;
  *wi_local = frame_to_local(frame, ls->wi);
  return sides_agree(ls->wi, su->ng, wi_local->z);
}

// MIS weight of a light sample against BSDF sampling (of b at wo_local) for the strategy.
inline float nee_weight(const LightSample* ls, int strategy, const Bsdf* b, float3 wo_local, float3 wi_local) {
  return (ls->delta || strategy == PT_STRATEGY_LIGHT) ? 1.0f : power_heuristic(ls->pdf, bsdf_pdf(b, wo_local, wi_local));
}
