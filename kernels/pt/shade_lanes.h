// pt_shade_lanes_<material>: a material queue shaded eight entries a work item, for CPU devices,
// where PoCL runs a work group's items one after another in scalar code (README "Tests and
// benchmarks"); the materials whose BSDF has a lane form (bsdf/bsdf_lanes.h: diffuse, smooth
// plastic). The estimator is pt_shade_hit's for such a hit, from the same random numbers: what
// touches memory per entry (the queue entry and its hit: pt_entry_hit; the material, the
// appends) runs lane by lane through the scalar helpers; the light samples are drawn on lanes
// for area lights and environment maps (light/light_lanes.h), lane by lane for the others; the
// arithmetic between (Philox, the frame, the BSDF's value, pdf and sample, MIS, Russian
// roulette) runs on float8 lanes. Included by pt.cl after pt_entry_hit and PT_SHADE_ARGS.
#pragma once
#include "path/lane_steps.h"

__attribute__((always_inline)) inline void pt_shade_lanes(
    int type, GdrPtParams params, uint count, uint first, int direct, __global const uint* sorted,
    __global const GdrRayHit* rays_in, __global const uint* queue_in, __global GdrRayHit* rays_out,
    __global uint* queue_out, __global GdrRay* shadow_rays, __global float4* shadow_values,
    __global GdrPathState* paths, __global float4* film, __global uint* counters, __local uint* scratch,
    const SceneData* sd) {
  SceneData s = *sd;
  __global uint* nonfinite = &counters[PT_COUNTER_NONFINITE];
  uint base = get_global_id(0) * LANES;

  // Per lane: the hit and the path at it (inactive lanes hold harmless values for the lane steps).
  uint slot[LANES], pixel[LANES], sample[LANES], depth[LANES];
  int active[LANES];
  LaneArray3 p, ng, ns, wo, beta;
  BsdfLaneArrays bsdf;
  for (int k = 0; k < LANES; ++k) {
    uint e = base + (uint)k, sl = 0u;
    GdrPathState st;
    GdrRayHit rh;
    Surface su;
    active[k] = 0;
    if (e < count && !path_no_segments(params.max_depth)) {
      uint q = direct ? e : sorted[first + e];
      sl = queue_in[q];
      st = paths[sl];
      rh = rays_in[q];
      active[k] = pt_entry_hit(&params, &s, direct, &rh, &paths[sl], &st, film, counters, &su) &&
                  !path_depth_reached(&st, params.max_depth);
    }
    if (!active[k]) {  // harmless values, written once: most lanes are active
      slot[k] = pixel[k] = sample[k] = depth[k] = 0u;
      lane_array3_set(&p, k, (float3)(0.0f));
      lane_array3_set(&ng, k, (float3)(0.0f, 0.0f, 1.0f));
      lane_array3_set(&ns, k, (float3)(0.0f, 0.0f, 1.0f));
      lane_array3_set(&wo, k, (float3)(0.0f, 0.0f, 1.0f));
      lane_array3_set(&beta, k, (float3)(0.0f));
      bsdf_lanes_clear(&bsdf, k);
      continue;
    }
    Bsdf b = surface_bsdf_of_type(&s, &su, type);
    active[k] = -1;  // a mask, as the lane steps' comparisons give
    slot[k] = sl;
    pixel[k] = st.pixel;
    sample[k] = st.sample;
    depth[k] = (uint)st.depth;
    bsdf_lanes_set(&bsdf, k, &b);
    lane_array3_set(&p, k, su.p);
    lane_array3_set(&ng, k, su.ng);
    lane_array3_set(&ns, k, su.ns);
    lane_array3_set(&wo, k, -(float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z));
    lane_array3_set(&beta, k, vload3(0, st.throughput));
  }

  // The light and BSDF blocks of every lane's numbers (path_state_sampler: no primary samples).
  uint8 depth8 = vload8(0, depth), pixel8 = vload8(0, pixel), sample8 = vload8(0, sample);
  RngBlockLanes ul = rng_block_lanes(params.seed, pixel8, sample8, RNG_BLOCK_LIGHT(depth8));
  RngBlockLanes ub = rng_block_lanes(params.seed, pixel8, sample8, RNG_BLOCK_BSDF(depth8));

  // Lanes: next-event estimation's contribution, then the BSDF sample and roulette.
  VertexLanes v = vertex_lanes(type, &bsdf, &ns, &ng, &wo);
  int nee_lane[LANES];
  int nee = params.strategy != PT_STRATEGY_BSDF && s.light_count > 0;
  for (int k = 0; k < LANES; ++k) nee_lane[k] = active[k] && nee;
  LightSampleLanes ls;
  Lanes3 f;
  float8 bsdf_pdf;
  int8 shadow_ok = nee_lanes(&s, &v, nee_lane, ul, &p, &ls, &f, &bsdf_pdf);
  Lanes3 BETA = lanes3_load(&beta);
  float8 lpdf = vload8(0, ls.pdf);
  int8 unweighted = (vload8(0, ls.delta) != 0) | (int8)(params.strategy == PT_STRATEGY_LIGHT ? -1 : 0);
  float8 w = select(power_heuristic_lanes(lpdf, bsdf_pdf), (float8)(1.0f), unweighted);
  Lanes3 c = lanes3_scale(lanes3_mul(lanes3_mul(BETA, f), lanes3_load(&ls.radiance)), w / lpdf);
  int8 c_positive = shadow_ok & (lanes3_max(c) > 0.0f);
  LaneArray3 shadow_value;
  lanes3_store(c, &shadow_value);
  int shadow[LANES], shadow_nonfinite[LANES];
  vstore8(c_positive & lanes3_finite(c), 0, shadow);
  vstore8(c_positive & ~lanes3_finite(c), 0, shadow_nonfinite);

  Lanes3 t = BETA, wi;
  float8 pdf;
  int8 delta, overflow;
  int8 survives = continue_lanes(&v, ub, convert_int8(depth8), params.rr_depth, &t, &wi, &pdf, &delta, &overflow);
  int8 on = vload8(0, active);
  LaneArray3 next_beta, next_wi;
  lanes3_store(t, &next_beta);
  lanes3_store(wi, &next_wi);
  float next_pdf[LANES];
  vstore8(pdf, 0, next_pdf);
  int next[LANES], next_nonfinite[LANES], next_delta[LANES];
  vstore8(on & survives, 0, next);
  vstore8(on & overflow, 0, next_nonfinite);
  vstore8(delta, 0, next_delta);

  // Per lane: the work item's appends, reserved with the group's.
  uint want[2] = {0u, 0u};
  for (int k = 0; k < LANES; ++k) {
    want[0] += shadow[k] ? 1u : 0u;
    want[1] += next[k] ? 1u : 0u;
    if (shadow_nonfinite[k]) atomic_inc(nonfinite);
    if (next_nonfinite[k]) atomic_inc(nonfinite);
  }
  const uint which[2] = {PT_COUNTER_SHADOW_RAYS, PT_COUNTER_NEXT_RAYS};
  group_reserve(scratch, counters, which, 2, want);
  for (int k = 0; k < LANES; ++k) {
    float3 pk = lane_array3_get(&p, k), ngk = lane_array3_get(&ng, k);
    if (shadow[k]) {
      write_light_ray(&shadow_rays[want[0]], pk, ngk, lane_array3_get(&ls.wi, k), ls.dist[k], pixel[k]);
      shadow_values[want[0]] = (float4)(lane_array3_get(&shadow_value, k), 0.0f);
      want[0] += 1u;
    }
    if (next[k]) {
      GdrPathState st;
      st.pixel = pixel[k];
      st.sample = sample[k];
      st.depth = (int)depth[k];
      BsdfSample bs;
      bs.pdf = next_pdf[k];
      bs.delta = next_delta[k];
      path_advance(&st, lane_array3_get(&next_beta, k), &bs);
      paths[slot[k]] = st;
      queue_out[want[1]] = slot[k];
      spawn_ray(&rays_out[want[1]], pk, ngk, lane_array3_get(&next_wi, k), slot[k]);
      want[1] += 1u;
    }
  }
}

// One kernel per material type with a lane form, compiled where the scene has it.
#define PT_SHADE_LANES_KERNEL(name, TYPE)                                                                    \
  __kernel void pt_shade_lanes_##name(PT_SHADE_ARGS) {                                                     \
    __local uint scratch[GROUP_RESERVE_SCRATCH];                                                           \
    SceneData s = path_scene(&params, SCENE_DATA_NAMES);                                                   \
    pt_shade_lanes(TYPE, params, count, first, direct, sorted, rays_in, queue_in, rays_out, queue_out,     \
                   shadow_rays, shadow_values, paths, film, counters, scratch, &s);                        \
  }
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_DIFFUSE)
PT_SHADE_LANES_KERNEL(diffuse, BSDF_DIFFUSE)
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_PLASTIC)
PT_SHADE_LANES_KERNEL(plastic, BSDF_PLASTIC)
#endif
