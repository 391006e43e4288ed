// G-BDPT's connections (s >= 2 light, t >= 2 camera vertices): each recorded camera vertex of a
// group (gbidir/camera_vertex.h), the base's and its offsets', connects to vertex j of the group's
// light subpath. The offset path of a connection is the base's with the camera prefix shifted: an
// offset at the base's vertex shares the base's connection segment; one at a vertex of its own
// reconnects there to the same light vertex (Manzi et al. 2015), which holds where that light
// vertex is diffuse too (the shift would copy the half vector toward a glossy one). Values wait
// in G-PT's pending slots for their shadow rays (gpt_shadow adds them).
#pragma once
#include "bidir/connection.h"
#include "gbidir/weights.h"
#include "path/film.h"
#include "shared/gbidir_types.h"
#include "shared/gpt_types.h"
#include "shift/policy.h"
#include "wavefront/counter_shard.h"
#include "wavefront/group_reserve.h"

// A group's connection segments to trace: offset k's own (own_from[k] to own_to[k]), then the
// base's (shared by the offsets at its vertex).
typedef struct {
  int own_ray_of[GPT_OFFSETS], base_ray;
  float3 own_from[GPT_OFFSETS], own_ng[GPT_OFFSETS], own_to[GPT_OFFSETS];
  float3 base_from, base_ng, base_to;
  uint rays;
} GbdptConnectAppend;

__attribute__((always_inline)) inline void gbdpt_connect_group(
    GdrGptParams params, uint g, uint j, uint stride, __global const GbdptCameraVertex* records,
    __global const GdrBidirPathState* light_paths, __global const GdrBidirVertex* store, __global float4* pend,
    __global uint* stats, GbdptConnectAppend* out, SCENE_DATA_ARGS) {
  if ((int)j >= light_paths[g].stored) return;
  GdrBidirVertex y = store[j * stride + g];
  GbdptCameraVertex rec = records[g];
  int max_depth = params.path.max_depth;
  if (max_depth >= 0 && rec.base.depth + y.depth + 1 > max_depth) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  __global uint* nonfinite = &stats[GPT_COUNTER_NONFINITE];
  GdrBidirOptions o = gbdpt_options(&params);
  // The base's vertex and the light vertex are evaluated once; offsets at the base's vertex share
  // them, and those that also share its direction (joined before it) the whole connection.
  ConnectionEnd ez = connection_end(&s, &rec.base), ey = connection_end(&s, &y);
  BidirConnection cx;
  if (!bidir_connection_ends(&ez, &rec.base, &ey, &y, &o, &cx)) return;
  atomic_inc(&stats[GPT_COUNTER_CONNECTIONS]);
  int y_diffuse = is_diffuse(&ey.b, params.shift_threshold);
  float2 ox = (float2)(cx.others, gbdpt_connection_all_others(&cx, rec.all_dvcm[0], rec.all_dvc[0], &o));

  for (int i = 0; i < GPT_PEND_COUNT; ++i) pend[g * GPT_PEND_COUNT + i] = (float4)(0.0f);
  int base_ray_needed = 0, glossy = 0;
#if defined(GDR_GBDPT_POWER_PRIMAL)
  float3 cp = checked(gbdpt_primal_connection(&cx, &y, &rec.base) * cx.value, nonfinite);
  pend[g * GPT_PEND_COUNT + GPT_PEND_PRIMAL] = (float4)(cp, 0.0f);
  base_ray_needed = max3(cp) > 0.0f;
#endif
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    int state = rec.state[k], formed = 0;
    BidirConnection cy;
    cy.value = (float3)(0.0f);
    cy.others = 0.0f;
    if (state == GBDPT_OFFSET_OWN && !y_diffuse) state = GBDPT_OFFSET_GLOSSY;
    glossy += state == GBDPT_OFFSET_GLOSSY;
    if (state == GBDPT_OFFSET_SHARED && all(vload3(0, rec.offset[k].wo) == vload3(0, rec.base.wo))) {
      cy = bidir_connection_rejoined(&cx, &rec.offset[k], &o);
      formed = 1;
    } else if (state == GBDPT_OFFSET_SHARED) {
      formed = bidir_connection_ends(&ez, &rec.offset[k], &ey, &y, &o, &cy);
    } else if (state == GBDPT_OFFSET_OWN) {
      ConnectionEnd eo = connection_end(&s, &rec.offset[k]);
      formed = bidir_connection_ends(&eo, &rec.offset[k], &ey, &y, &o, &cy);
    }
    float2 oy = (float2)(0.0f);
    if (formed) oy = (float2)(cy.others, gbdpt_connection_all_others(&cy, rec.all_dvcm[1 + k], rec.all_dvc[1 + k], &o));
    float2 w = gbdpt_pair_weights(ox, oy, rec.ratio[k], formed);
    float3 cb = checked(w.x * cx.value, nonfinite), co = checked(w.y * cy.value, nonfinite);
    pend[g * GPT_PEND_COUNT + GPT_PEND_BASE(k)] = (float4)(cb, 0.0f);
    base_ray_needed |= max3(cb) > 0.0f;
    if (!formed || !(max3(co) > 0.0f)) continue;
    if (state == GBDPT_OFFSET_SHARED) {
      pend[g * GPT_PEND_COUNT + GPT_PEND_JOINED(k)] = (float4)(co, 0.0f);
      base_ray_needed = 1;
    } else {
      pend[g * GPT_PEND_COUNT + GPT_PEND_OWN(k)] = (float4)(co, 0.0f);
      out->own_ray_of[k] = 1;
      out->own_from[k] = cy.from;
      out->own_ng[k] = cy.from_ng;
      out->own_to[k] = cy.to;
      ++out->rays;
    }
  }
  if (glossy) atomic_add(&stats[GPT_COUNTER_FAIL_GLOSSY_CONNECTION], (uint)glossy);
  if (base_ray_needed) {
    out->base_ray = 1;
    out->base_from = cx.from;
    out->base_ng = cx.from_ng;
    out->base_to = cx.to;
    ++out->rays;
  }
}

// The connections of the groups queued in `connectable`; each work-group appends its segments
// together (group_reserve).
__kernel void gbdpt_connect(GdrGptParams params, uint count, uint j, uint stride, __global const uint* connectable,
                            __global const GbdptCameraVertex* records, __global const GdrBidirPathState* light_paths,
                            __global const GdrBidirVertex* store, __global GdrRay* shadow_rays, __global float4* pend,
                            __global uint* counters, SCENE_DATA_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint q = get_global_id(0);
  uint g = q < count ? connectable[q] : 0u;
  GbdptConnectAppend out;
  out.base_ray = 0;
  out.rays = 0u;
  for (int k = 0; k < GPT_OFFSETS; ++k) out.own_ray_of[k] = 0;
  if (q < count) {
    gbdpt_connect_group(params, g, j, stride, records, light_paths, store, pend, counter_shard(counters), &out,
                        SCENE_DATA_NAMES);
  }
  const uint which[1] = {GPT_COUNTER_SHADOW_RAYS};
  uint r = out.rays;
  group_reserve(scratch, counters, which, 1, &r);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (out.own_ray_of[k]) write_segment_ray(&shadow_rays[r++], out.own_from[k], out.own_ng[k], out.own_to[k],
                                              GPT_SHADOW_ID(g, 1 + k));
  }
  if (out.base_ray) write_segment_ray(&shadow_rays[r], out.base_from, out.base_ng, out.base_to, GPT_SHADOW_ID(g, 0));
}
