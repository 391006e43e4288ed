// G-PT's manifold shift (--shift manifold): where the base leaves a rough vertex x_b into a chain
// of specular vertices, the traced offsets at rough vertices wait (GPT_MODE_MANIFOLD) while the
// base records its chain (GptChain). When the base reaches the next rough vertex x_c, each
// waiting offset gets a manifold walk from its own vertex to x_c (kernels/manifold/walk.h, run by
// the host's manifold stage); gpt_manifold_join then turns a solved walk into the offset's prefix
// up to x_c, where it has joined the base. A failed walk, a chain that escapes or grows past
// MANIFOLD_MAX_CHAIN vertices: the offset contributes zero and its base takes the full weight.
#pragma once
#include "gbidir/weights.h"
#include "gradient/offsets.h"
#include "manifold/walk.h"
#include "shift/policy.h"

inline GdrManifoldPoint manifold_point(uint prim, float b1, float b2) {
  GdrManifoldPoint q = {prim, b1, b2};
  return q;
}

inline void kill_waiting(__global GptOffsetState* offsets, uint g, __global uint* counters, int reason) {
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    GptOffsetState o = offsets[g * GPT_OFFSETS + k];
    if (o.mode != GPT_MODE_MANIFOLD) continue;
    kill_offset(&o, counters, reason);
    offsets[g * GPT_OFFSETS + k] = o;
  }
}

// The base has sampled at x_k (x) and found its next vertex (next, at hit point q). Records the
// chain, starts the walks of a chain that has closed, and starts a chain where the base leaves a
// rough vertex for a specular one (the traced offsets at rough vertices then wait for it).
inline void gpt_chain_step(const SceneData* sd, uint g, const GptBaseState* base, const ShiftBase* x,
                           const ShiftNext* next, GdrManifoldPoint q, __global GptChain* chains,
                           __global GptOffsetState* offsets, __global GdrManifoldWalk* walks,
                           __global uint* counters, float threshold) {
  GptChain c = chains[g];
  if (c.open) {
    int j = c.count - 1;
    int flags = (x->delta ? MANIFOLD_VERTEX_DELTA : 0) | (x->transmitted ? MANIFOLD_VERTEX_TRANSMIT : 0);
    c.v[j].flags = flags;
    c.pdf[j] = x->pdf;
    c.rr[j] = x->rr_prob;
    int ok = 1;
    if (!x->delta) {
      // A near-specular vertex keeps the micro-normal the base scattered about.
      ManifoldSurface ms = manifold_surface(sd, c.v[j].at);
      mreal3 wa = to_mreal3(vload3(0, base->wo)), wb = to_mreal3(x->wi_world), h;
      ok = manifold_half_vector(&ms, flags, manifold_etas(sd, &ms, flags, wa), wa, wb, &h);
      c.v[j].h[0] = (float)h.x;
      c.v[j].h[1] = (float)h.y;
      c.v[j].h[2] = (float)h.z;
    }
    if (!ok) {
      c.open = 0;
      kill_waiting(offsets, g, counters, GPT_COUNTER_FAIL_ZERO);
    } else if (!next->hit) {
      c.open = 0;
      kill_waiting(offsets, g, counters, GPT_COUNTER_FAIL_ENVIRONMENT);
    } else if (!next->diffuse) {
      if (c.count == MANIFOLD_MAX_CHAIN) {
        c.open = 0;
        kill_waiting(offsets, g, counters, GPT_COUNTER_FAIL_CHAIN_LONG);
      } else {
        c.v[c.count++].at = q;
      }
    } else {
      // Closed at x_c = q: a walk per waiting offset.
      c.open = 0;
      for (int k = 0; k < GPT_OFFSETS; ++k) {
        GptOffsetState o = offsets[g * GPT_OFFSETS + k];
        if (o.mode != GPT_MODE_MANIFOLD) continue;
        GdrManifoldWalk w;
        w.start = manifold_point(o.prim, o.b1, o.b2);
        w.end = q;
        w.origin = c.origin;
        w.count = c.count;
        w.owner = g * GPT_OFFSETS + (uint)k;
        w.pad0 = 0;
        for (int i = 0; i < MANIFOLD_MAX_CHAIN; ++i) w.v[i] = c.v[i];
        walks[atomic_inc(&counters[GPT_COUNTER_MANIFOLD_WALKS])] = w;
      }
    }
    chains[g] = c;
    return;
  }
  if (!(x->diffuse && !x->delta && next->hit && !next->diffuse)) return;
  int waiting = 0;
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    __global GptOffsetState* o = &offsets[g * GPT_OFFSETS + k];
    if (o->mode != GPT_MODE_TRACE) continue;
    Surface su = surface_at(sd, o->prim, o->b1, o->b2);
    Bsdf b = surface_bsdf(sd, &su);
    if (!is_diffuse(&b, threshold)) continue;
    o->mode = GPT_MODE_MANIFOLD;
    waiting = 1;
  }
  if (!waiting) return;
  c.open = 1;
  c.count = 1;
  c.origin = manifold_point(base->prim, base->b1, base->b2);
  c.origin_pdf = x->pdf;
  c.origin_rr = x->rr_prob;
  c.v[0].at = q;
  chains[g] = c;
}

// The half-vector Jacobian |d h / d w_b| at a near-specular chain vertex between w_a and w_b.
inline float chain_half_jacobian(const SceneData* sd, GdrManifoldPoint at, int flags, float3 wa, float3 wb) {
  ManifoldSurface ms = manifold_surface(sd, at);
  mreal2 eta = manifold_etas(sd, &ms, flags, to_mreal3(wa));
  float ea = (float)eta.x, eb = (float)eta.y;
  float3 h = normalize(ea * wa + eb * wb);
  if (!(flags & MANIFOLD_VERTEX_TRANSMIT)) return half_jacobian_reflect(wb, h);
  return half_jacobian_refract(wa, wb, h, eb / ea);
}

// A solved walk becomes the offset's prefix up to x_c: its own BSDF toward the new chain, the
// chain's lobes, and the Jacobian g_walk / g_origin (times the half-vector Jacobians of
// near-specular vertices), over the base's pdfs; the base's Russian roulette carried over. Built
// for G-BDPT (GDR_GBDPT), the offset's bidirectional sums scatter at its vertex toward the new
// chain and pass through the chain's vertices as the base's did (arrival at x_c is the shade
// step's, as for every offset that joins there).
__kernel void gpt_manifold_join(GdrGptParams params, uint count, __global const GdrManifoldWalk* walks,
                                __global const GdrManifoldResult* results, __global const GptChain* chains,
                                __global GptOffsetState* offsets, __global uint* counters, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  GdrManifoldWalk W = walks[i];
  GdrManifoldResult R = results[i];
  uint g = W.owner / GPT_OFFSETS;
  GptOffsetState o = offsets[W.owner];
  GptChain c = chains[g];
  const int m = W.count;
  int reason = R.status ? GPT_COUNTER_FAIL_MANIFOLD : 0;
  if (!reason && !(R.g_origin > 0.0f && R.g_walk > 0.0f)) reason = GPT_COUNTER_FAIL_ZERO;
  ShiftPrefix pre = offset_prefix(&o);
#if defined(GDR_GBDPT)
  GdrBidirOptions mo = gbdpt_options(&params);
#endif
  float3 off[MANIFOLD_MAX_CHAIN + 2], bp[MANIFOLD_MAX_CHAIN + 2];
  if (!reason) {
    ShiftVertex y = shift_vertex_at(&s, o.prim, o.b1, o.b2, -vload3(0, o.dir), params.shift_threshold);
    off[0] = y.su.p;
    bp[0] = manifold_point_on(&s, c.origin);
    for (int k = 0; k < m; ++k) {
      off[k + 1] = manifold_point_on(&s, R.v[k]);
      bp[k + 1] = manifold_point_on(&s, W.v[k].at);
    }
    off[m + 1] = bp[m + 1] = manifold_point_on(&s, W.end);
    float3 wi = normalize(off[1] - off[0]);
    float3 wil = frame_to_local(&y.frame, wi);
    float3 f = bsdf_eval(&y.b, y.wo, wil);
    float p = bsdf_pdf(&y.b, y.wo, wil);
    if (!(p > 0.0f) || max3(f) <= 0.0f || !sides_agree(wi, y.su.ng, wil.z)) reason = GPT_COUNTER_FAIL_ZERO;
    pre.throughput *= f / c.origin_pdf;
    pre.ratio *= p / c.origin_pdf;
    if (c.origin_rr < 1.0f) shift_roulette(&pre, c.origin_rr);
#if defined(GDR_GBDPT)
    gbdpt_sums_scatter(0, p, bsdf_pdf(&y.b, wil, y.wo), fabs(dot(y.su.ng, wi)), &mo, &o.mis);
#endif
  }
  float jac = R.g_walk / R.g_origin;
  for (int k = 0; k < m && !reason; ++k) {
    Surface su = surface_at(&s, R.v[k].prim, R.v[k].b1, R.v[k].b2);
    Bsdf b = surface_bsdf(&s, &su);
    Frame fr = frame_from_normal(su.ns);
    float3 wa = normalize(off[k] - off[k + 1]), wb = normalize(off[k + 2] - off[k + 1]);
    float3 wal = frame_to_local(&fr, wa), wbl = frame_to_local(&fr, wb);
    int flags = W.v[k].flags;
#if defined(GDR_GBDPT)
    gbdpt_sums_arrive(length(off[k + 1] - off[k]), fabs(dot(su.ng, wa)), &o.mis);
#endif
    if (flags & MANIFOLD_VERTEX_DELTA) {
      BsdfSample so;
      if (!bsdf_sample_delta_lobe(&b, wal, (flags & MANIFOLD_VERTEX_TRANSMIT) != 0, &so)) {
        reason = GPT_COUNTER_FAIL_LOBE;
        break;
      }
      pre.throughput *= so.weight * (so.pdf / c.pdf[k]);
      pre.ratio *= so.pdf / c.pdf[k];
      pre.last_pdf = so.pdf;
      pre.last_delta = 1;
#if defined(GDR_GBDPT)
      gbdpt_sums_scatter(1, so.pdf, 0.0f, fabs(dot(su.ng, wb)), &mo, &o.mis);
#endif
    } else {
      float3 f = bsdf_eval(&b, wal, wbl);
      float p = bsdf_pdf(&b, wal, wbl);
      float3 ba = normalize(bp[k] - bp[k + 1]), bb = normalize(bp[k + 2] - bp[k + 1]);
      jac *= safe_div(chain_half_jacobian(&s, W.v[k].at, flags, ba, bb),
                      chain_half_jacobian(&s, R.v[k], flags, wa, wb));
      if (!(p > 0.0f) || max3(f) <= 0.0f) {
        reason = GPT_COUNTER_FAIL_ZERO;
        break;
      }
      pre.throughput *= f / c.pdf[k];
      pre.ratio *= p / c.pdf[k];
      pre.last_pdf = p;
      pre.last_delta = 0;
#if defined(GDR_GBDPT)
      gbdpt_sums_scatter(0, p, bsdf_pdf(&b, wbl, wal), fabs(dot(su.ng, wb)), &mo, &o.mis);
#endif
    }
    if (!sides_agree(wb, su.ng, wbl.z)) reason = GPT_COUNTER_FAIL_ZERO;
    if (c.rr[k] < 1.0f) shift_roulette(&pre, c.rr[k]);
  }
  if (!reason) {
    pre.throughput *= jac;
    pre.ratio *= jac;
    if (!shift_prefix_finite(&pre) || !(jac > 0.0f)) reason = GPT_COUNTER_FAIL_NONFINITE;
  }
  if (reason) {
    kill_offset(&o, counters, reason);
  } else {
    offset_keep(&o, &pre);
    o.mode = GPT_MODE_JOINED_RECENT;
    vstore3(off[m], 0, o.prev_pos);
    atomic_inc(&counters[GPT_COUNTER_SHIFT_MANIFOLD]);
  }
  offsets[W.owner] = o;
}
