// G-PT shift step: with the base's next vertex known, every traced offset follows the base's
// scattering at its own vertex (shift/policy.h: reconnection, half-vector copy, delta-lobe copy
// or replay).
#pragma once
#include "gradient/offsets.h"
#include "path/scene.h"
#include "path/spawn.h"
#include "sampling/path_sampler.h"
#include "shift/policy.h"
#include "wavefront/counter_shard.h"
#include "wavefront/group_reserve.h"
#if defined(GDR_MANIFOLD)
#include "gpt/manifold_step.h"
#endif
#include "gbidir/weights.h"

// What a group's shift step appends to the queues: per offset none (0), its own ray (1) or a
// reconnection toward the base's next vertex (2), from its vertex.
typedef struct {
  int kind[GPT_OFFSETS];
  float3 p[GPT_OFFSETS], ng[GPT_OFFSETS], w[GPT_OFFSETS];
  float3 next_p;
  uint own, reconnects;
} GptShiftAppend;

// The base's next vertex x_{k+1} is known: every traced offset of group `base_rays[q].ray.id`
// shifts its outgoing direction.
__attribute__((always_inline)) inline void gpt_shift_group(GdrGptParams params, uint q,
                                                           __global const GdrRayHit* base_rays,
                                                           __global const GptBaseState* bases,
                                                           __global GptOffsetState* offsets, __global GptChain* chains,
                                                           __global GdrManifoldWalk* walks, __global uint* counters,
                                                           GptShiftAppend* out, PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  __global uint* stats = counter_shard(counters);
  GdrRayHit rh = base_rays[q];
  uint g = rh.ray.id;
  GptBaseState base = bases[g];
  float thr = params.shift_threshold;
  // The base's scattering at x_k (shade step's sample), shared by the four offsets.
  Surface sx = surface_at(&s, base.prim, base.b1, base.b2);
  Bsdf bx = surface_bsdf(&s, &sx);
  Frame fx = frame_from_normal(sx.ns);
  ShiftBase x;
  x.p = sx.p;
  x.wo = frame_to_local(&fx, vload3(0, base.wo));
  x.wi_world = vload3(0, base.wi);
  x.wi = frame_to_local(&fx, x.wi_world);
  x.pdf = base.path.bsdf_pdf;
  x.eta = base.sample_eta;
  x.rr_prob = base.rr_prob;
  x.delta = base.sample_delta;
  x.transmitted = base.sample_transmitted;
  x.diffuse = is_diffuse(&bx, thr);
  PathSampler ps = path_state_sampler_bound(&base.path, params.path.seed, PRIMARY_SAMPLE_NAMES);
  x.u = sampler_block(&ps, RNG_BLOCK_BSDF(base.path.depth - 1));
  // The base's next vertex.
  ShiftNext next;
  next.hit = rh.hit.geomID != GDR_INVALID_ID;
  next.diffuse = 0;
  next.p = sx.p;
  next.ng = sx.ng;
  if (next.hit) {
    Surface sn = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
    Bsdf bn = surface_bsdf(&s, &sn);
    next.diffuse = is_diffuse(&bn, thr);
    next.p = sn.p;
    next.ng = sn.ng;
  }
#if defined(GDR_MANIFOLD)
  if (params.shift == GPT_SHIFT_MANIFOLD) {
    GdrManifoldPoint q = {rh.hit.primID, rh.hit.u, rh.hit.v};
    gpt_chain_step(&s, g, &base, &x, &next, q, chains, offsets, walks, counters, thr);
  }
#endif

#if defined(GDR_GBDPT)
  GdrBidirOptions mo = gbdpt_options(&params);  // the options the offsets' sums take
#endif
  out->next_p = next.p;
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    __global GptOffsetState* og = &offsets[g * GPT_OFFSETS + k];
    if (og->mode != GPT_MODE_TRACE) continue;
    GptOffsetState o = *og;
    ShiftVertex y = shift_vertex_at(&s, o.prim, o.b1, o.b2, -vload3(0, o.dir), thr);
    ShiftPrefix pre = offset_prefix(&o);
    float3 wiy_w;  // the offset's new direction (world)
    int reconnect, glossy_next_only;
    int reason = shift_offset(params.shift, &x, &next, &y, &pre, &wiy_w, &reconnect, &glossy_next_only, stats);
    if (reason) {
      kill_offset(&o, stats, reason);
      *og = o;
      continue;
    }
    offset_keep(&o, &pre);
#if defined(GDR_GBDPT)
    gbdpt_sums_scatter(o.last_delta, o.last_pdf, bsdf_pdf(&y.b, frame_to_local(&y.frame, wiy_w), y.wo),
                       fabs(dot(y.su.ng, wiy_w)), &mo, &o.mis);
#endif
    o.glossy_next_only = glossy_next_only;
    vstore3(y.su.p, 0, o.prev_pos);
    vstore3(wiy_w, 0, o.dir);
    if (reconnect) {
      o.mode = GPT_MODE_RECONNECTING;
      o.visible = 0;
    }
    out->kind[k] = reconnect ? 2 : 1;
    out->own += !reconnect;
    out->reconnects += reconnect;
    out->p[k] = y.su.p;
    out->ng[k] = y.su.ng;
    out->w[k] = wiy_w;
    *og = o;
  }
}

// The shift step of the groups the shade step listed (shift_groups: their entries in base_rays);
// each work-group appends its offsets' rays together (group_reserve).
__kernel void gpt_shift(GdrGptParams params, uint count, __global const uint* shift_groups,
                        __global const GdrRayHit* base_rays, __global GdrRayHit* offset_rays,
                        __global GdrRay* reconnect_rays, __global const GptBaseState* bases,
                        __global GptOffsetState* offsets, __global GptChain* chains,
                        __global GdrManifoldWalk* walks, __global uint* counters,
                        PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint i = get_global_id(0);
  uint q = i < count ? shift_groups[i] : 0u;
  GptShiftAppend out;
  out.own = out.reconnects = 0u;
  for (int k = 0; k < GPT_OFFSETS; ++k) out.kind[k] = 0;
  if (i < count) {
    gpt_shift_group(params, q, base_rays, bases, offsets, chains, walks, counters, &out, PRIMARY_SAMPLE_NAMES,
                    SCENE_DATA_NAMES);
  }
  const uint which[2] = {GPT_COUNTER_OFFSET_RAYS, GPT_COUNTER_RECONNECT_RAYS};
  uint slot[2] = {out.own, out.reconnects};
  group_reserve(scratch, counters, which, 2, slot);
  if (out.own + out.reconnects == 0u) return;
  uint g = base_rays[q].ray.id;
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    uint id = g * GPT_OFFSETS + (uint)k;
    if (out.kind[k] == 2) write_segment_ray(&reconnect_rays[slot[1]++], out.p[k], out.ng[k], out.next_p, id);
    if (out.kind[k] == 1) spawn_ray(&offset_rays[slot[0]++], out.p[k], out.ng[k], out.w[k], id);
  }
}
