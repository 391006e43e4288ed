// pt_route_lanes: pt_route for eight queue entries a work item (CPU devices, as pt/shade_lanes.h):
// the hits' keys entry by entry; what the misses see of the environment on float8 lanes
// (light/light_lanes.h), then added to the film entry by entry. Included by pt.cl.
#pragma once
#include "core/lanes.h"
#include "light/light_lanes.h"

__kernel void pt_route_lanes(GdrPtParams params, uint count, __global const GdrRayHit* rays_in,
                             __global const uint* queue_in, __global uint* keys, __global const GdrPathState* paths,
                             __global float4* film, __global uint* counters, SCENE_DATA_ARGS) {
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  uint base = get_global_id(0) * LANES;
  int miss[LANES], unweighted[LANES], any = 0;
  uint pixel[LANES];
  float bsdf_pdf[LANES];
  LaneArray3 dir, beta;
  for (int k = 0; k < LANES; ++k) {
    miss[k] = unweighted[k] = 0;
    pixel[k] = 0u;
    bsdf_pdf[k] = 1.0f;
    lane_array3_set(&dir, k, (float3)(0.0f, 0.0f, 1.0f));
    lane_array3_set(&beta, k, (float3)(0.0f));
    uint q = base + (uint)k;
    if (q >= count) continue;
    __global const GdrRayHit* rh = &rays_in[q];
    if (rh->hit.geomID != GDR_INVALID_ID) {
      keys[q] = material_queue_key(&s, rh->hit.primID);
      continue;
    }
    keys[q] = MATERIAL_QUEUE_NONE;
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    if (s.env_light < 0 || path_no_segments(params.max_depth)) continue;
    GdrPathState st = paths[queue_in[q]];
    miss[k] = -1;  // a mask, as the lane steps' comparisons give
    any = 1;
    pixel[k] = st.pixel;
    unweighted[k] = emission_unweighted(&st, params.strategy) ? -1 : 0;
    bsdf_pdf[k] = st.bsdf_pdf;
    lane_array3_set(&dir, k, (float3)(rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z));
    lane_array3_set(&beta, k, vload3(0, st.throughput));
#endif
  }
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
  if (!any) return;
  float8 light_pdf;
  Lanes3 le = environment_eval_lanes(&s, vload8(0, miss), lanes3_load(&dir), &light_pdf);
  // emission_weight: 1, else 0 under light sampling alone, else the power heuristic.
  float8 w = power_heuristic_lanes(vload8(0, bsdf_pdf), light_pdf);
  if (params.strategy == PT_STRATEGY_LIGHT) w = (float8)(0.0f);
  w = select(w, (float8)(1.0f), vload8(0, unweighted));
  LaneArray3 c;
  lanes3_store(lanes3_scale(lanes3_mul(lanes3_load(&beta), le), w), &c);
  for (int k = 0; k < LANES; ++k) {
    if (miss[k]) film_add(film, pixel[k], lane_array3_get(&c, k), &counters[PT_COUNTER_NONFINITE]);
  }
#endif
}
