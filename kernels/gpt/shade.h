// G-PT shade step: emission and next-event estimation of the base and its offsets with the
// pairwise MIS weights, then the base's BSDF sample (offsets that share its vertex follow).
// Built for G-BDPT (GDR_GBDPT), the same step weighs by G-BDPT's MIS (gbidir/weights.h), carries
// the paths' bidirectional sums and records each rough vertex for the connections to the light
// subpath (gbidir/connect.h), and for G-VCM (GDR_GVCM too) for the merges (gbidir/merge.h).
// Built for G-PM (GDR_GPM), it is a photon mapper's camera subpath:
// no next-event estimation, emission only through delta vertices (under the pair weight alone),
// and the group ends at the base's first rough vertex, recorded for the merges (gbidir/merge.h).
#pragma once
#include "gradient/accumulators.h"
#include "gradient/offsets.h"
#include "path/continuation.h"
#include "path/emission.h"
#include "path/film.h"
#include "path/material_queues.h"
#include "path/nee.h"
#include "path/scene.h"
#include "path/shadow.h"
#include "path/spawn.h"
#include "shared/gbidir_types.h"
#include "shift/joined.h"
#include "shift/policy.h"
#include "wavefront/counter_shard.h"
#include "wavefront/group_reserve.h"
#include "gbidir/camera_vertex.h"
#include "gbidir/weights.h"

// The "others" of the strategy that found emission, of the base (x) and of the offset (y): G-BDPT's
// from the bidirectional sums; G-PM's subpaths see emission through delta vertices only, by one
// strategy, so none. (Fixed arities: NVIDIA's OpenCL compiler refuses variadic macros.)
#if defined(GDR_GPM)
#define GPT_ESCAPED_EMISSION_OTHERS(s, dir, m) ((float2)(0.0f))
#define GPT_SURFACE_EMISSION_OTHERS(s, su, wo, m) ((float2)(0.0f))
#else
#define GPT_ESCAPED_EMISSION_OTHERS(s, dir, m) gbdpt_escaped_emission_others(s, dir, m)
#define GPT_SURFACE_EMISSION_OTHERS(s, su, wo, m) gbdpt_surface_emission_others(s, su, wo, m)
#endif

// Emission found by BSDF sampling, for the pair (base, offset k): the base's contribution c_base
// and the offset's le_off (with q_off, the offset's own light-sampling pdf for that emitter),
// each weighted by gpt_weight with its own pdfs. A dead offset leaves plain path-tracing MIS.
inline void add_bsdf_emission(__global float4* acc, uint pixel, int k, const GptOffsetState* o, float p_bsdf,
                              float p_light, float3 c_base, float3 le_off, float q_off, __global uint* nonfinite) {
  float r = 0.0f;
  float3 c_off = (float3)(0.0f);
  if (offset_alive(o)) {
    r = o->ratio;
    c_off = vload3(0, o->throughput) * le_off * gpt_weight(o->last_pdf, q_off, r);
  }
  acc_add(acc, pixel, GPT_ACC_BASE(k), checked(gpt_weight(p_bsdf, p_light, r) * c_base, nonfinite));
  acc_add(acc, pixel, GPT_ACC_OFFSET(k), checked(c_off, nonfinite));
}

// Emission the camera sees directly (w = 1), or the base's share c under the primal's weight w,
// into G-BDPT's own primal. Elsewhere nothing: no check (the direct layer's add counts a
// non-finite value once), and the weight, unused, is not computed.
inline void add_own_primal(__global float4* acc, uint pixel, float w, float3 c, __global uint* nonfinite) {
#if defined(GDR_GBDPT_POWER_PRIMAL)
  acc_add(acc, pixel, GPT_ACC_PRIMAL, checked(w * c, nonfinite));
#endif
}

// The pair (base, offset k) of one strategy under G-BDPT's weights w (base, offset): the base's
// c_base and the offset's c_off (f(y) |J| / p(x)).
inline void add_pair(__global float4* acc, uint pixel, int k, float2 w, float3 c_base, float3 c_off,
                     __global uint* nonfinite) {
  acc_add(acc, pixel, GPT_ACC_BASE(k), checked(w.x * c_base, nonfinite));
  acc_add(acc, pixel, GPT_ACC_OFFSET(k), checked(w.y * c_off, nonfinite));
}

// What a group's shade step appends to the queues: its shadow rays (the offsets' own, then the
// base's), its record's entry in the connectable list, the base's next ray and, where an offset
// is still traced or waits for a manifold walk, the group's entry in the shift step's list.
typedef struct {
  float3 shadow_p[GPT_OFFSETS + 1], shadow_ng[GPT_OFFSETS + 1], shadow_wi[GPT_OFFSETS + 1];
  float shadow_dist[GPT_OFFSETS + 1];
  uint shadow_id[GPT_OFFSETS + 1];
  uint shadows, connectable, next, shift;
  float3 next_p, next_ng, next_wi;
} GptShadeAppend;

inline void shade_append_shadow(GptShadeAppend* out, float3 p, float3 ng, const LightSample* ls, uint id) {
  uint j = out->shadows++;
  out->shadow_p[j] = p;
  out->shadow_ng[j] = ng;
  out->shadow_wi[j] = ls->wi;
  out->shadow_dist[j] = ls->dist;
  out->shadow_id[j] = id;
}

// Group g's step (the queue's entry q), up to what it appends (*out); its counts go to `stats`.
// The base's hit is of BSDF type `type` (its material queue's; < 0: any); a miss appends nothing.
__attribute__((always_inline)) inline void gpt_shade_group(
    GdrGptParams params, uint q, int type, __global const GdrRayHit* base_in, __global GptBaseState* bases,
    __global GptOffsetState* offsets, __global float4* acc, __global float4* pend, __global GbdptCameraVertex* records,
    __global uint* stats, GptShadeAppend* out, PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  __global uint* nonfinite = &stats[GPT_COUNTER_NONFINITE];
  GdrRayHit rh = base_in[q];
  uint g = rh.ray.id;
  GptBaseState base = bases[g];
  GdrPathState* st = &base.path;
  GptOffsetState o[GPT_OFFSETS];
  for (int k = 0; k < GPT_OFFSETS; ++k) o[k] = offsets[g * GPT_OFFSETS + k];

  float3 dir = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  float3 beta = vload3(0, st->throughput);
  int base_hit = rh.hit.geomID != GDR_INVALID_ID;
  int direct = st->depth == 0;  // emission seen from the camera stays out of the gradients

  // Outcomes of the last shift step: where each offset got to.
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (o[k].mode == GPT_MODE_TRACE && (o[k].prim != GDR_INVALID_ID) != base_hit) {
      kill_offset(&o[k], stats, GPT_COUNTER_FAIL_ENVIRONMENT);
    } else if (o[k].mode == GPT_MODE_RECONNECTING) {
      if (o[k].visible) o[k].mode = GPT_MODE_JOINED_RECENT;
      else kill_offset(&o[k], stats, GPT_COUNTER_FAIL_OCCLUDED);
    }
  }

  float p_bsdf = st->bsdf_pdf;
  int last_specular = (st->flags & PATH_FLAG_SPECULAR) != 0;

  if (!base_hit) {
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    if (s.env_light >= 0) {
      float p_env;
      float3 le = environment_eval(&s, dir, &p_env);
      if (direct) {
        acc_add_seen(acc, st->pixel, checked(beta * le, nonfinite));
      } else {
#if defined(GDR_GBDPT) || defined(GDR_GPM)
        float2 others_x = GPT_ESCAPED_EMISSION_OTHERS(&s, dir, &base.mis);
        add_own_primal(acc, st->pixel, gbdpt_primal_escaped_emission(&s, dir, &base.mis), beta * le, nonfinite);
#else
        float p_light = last_specular ? 0.0f : p_env;
#endif
        for (int k = 0; k < GPT_OFFSETS; ++k) {
          // A traced offset escaped along its own direction; a joined one along the base's, and
          // sees the base's radiance (and pdf).
          int own = o[k].mode == GPT_MODE_TRACE;
          float3 d_off = own ? vload3(0, o[k].dir) : dir;
#if defined(GDR_GBDPT) || defined(GDR_GPM)
          int alive = offset_alive(&o[k]);
          float2 others_y = alive ? GPT_ESCAPED_EMISSION_OTHERS(&s, d_off, &o[k].mis) : (float2)(0.0f);
          float3 le_off = own ? escaped_radiance(&s, d_off) : le;
          float3 c_off = alive ? vload3(0, o[k].throughput) * le_off : (float3)(0.0f);
          add_pair(acc, st->pixel, k, gbdpt_pair_weights(others_x, others_y, o[k].ratio, alive), beta * le, c_off,
                   nonfinite);
#else
          float q_env = p_env;
          float3 le_off = own ? environment_eval(&s, d_off, &q_env) : le;
          float q_off = o[k].last_delta ? 0.0f : q_env;
          add_bsdf_emission(acc, st->pixel, k, &o[k], p_bsdf, p_light, beta * le, le_off, q_off, nonfinite);
#endif
        }
      }
    }
#endif
    for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];
    return;
  }

  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  float3 wo = -dir;
  Surface so[GPT_OFFSETS];   // the offsets' current vertices
  float3 wo_off[GPT_OFFSETS];  // and their directions toward their previous vertices (world)
  float dist_off[GPT_OFFSETS]; // and their distances from them
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    so[k] = su;
    wo_off[k] = wo;
    dist_off[k] = rh.ray.tfar;
    if (o[k].mode == GPT_MODE_TRACE) {
      so[k] = surface_at(&s, o[k].prim, o[k].b1, o[k].b2);
      wo_off[k] = -vload3(0, o[k].dir);
      dist_off[k] = o[k].t;
      if (o[k].glossy_next_only) {
        Bsdf bo = surface_bsdf(&s, &so[k]);
        if (!shift_reverses_at(&bo, params.shift_threshold)) {
          kill_offset(&o[k], stats, GPT_COUNTER_FAIL_NOT_INVERTIBLE);
        }
      }
    } else if (o[k].mode == GPT_MODE_JOINED_RECENT) {
      wo_off[k] = normalize_or(vload3(0, o[k].prev_pos) - su.p, wo);
      dist_off[k] = length(vload3(0, o[k].prev_pos) - su.p);
    }
  }
#if defined(GDR_GBDPT)
  GdrBidirOptions mo = gbdpt_options(&params);  // the options the sums and weights take
  // The bidirectional sums arrive at the paths' vertices.
  gbdpt_sums_arrive(rh.ray.tfar, fabs(dot(su.ng, wo)), &base.mis);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (offset_alive(&o[k])) gbdpt_sums_arrive(dist_off[k], fabs(dot(so[k].ng, wo_off[k])), &o[k].mis);
  }
#endif

#if defined(GDR_LIGHT_AREA)
  // Emission found by BSDF sampling.
  if (su.light >= 0 || !direct) {
    float3 le = su.light >= 0 ? surface_radiance(&s, &su, wo) : (float3)(0.0f);
    if (direct) {
      acc_add_seen(acc, st->pixel, checked(beta * le, nonfinite));
    } else {
#if defined(GDR_GBDPT) || defined(GDR_GPM)
      float2 others_x = GPT_SURFACE_EMISSION_OTHERS(&s, &su, wo, &base.mis);
      add_own_primal(acc, st->pixel, gbdpt_primal_surface_emission(&s, &su, wo, &base.mis), beta * le, nonfinite);
      for (int k = 0; k < GPT_OFFSETS; ++k) {
        int alive = offset_alive(&o[k]);
        float3 c_off = (float3)(0.0f);
        float2 others_y = (float2)(0.0f);
        if (alive && so[k].light >= 0) {
          c_off = vload3(0, o[k].throughput) * surface_radiance(&s, &so[k], wo_off[k]);
          others_y = GPT_SURFACE_EMISSION_OTHERS(&s, &so[k], wo_off[k], &o[k].mis);
        }
        add_pair(acc, st->pixel, k, gbdpt_pair_weights(others_x, others_y, o[k].ratio, alive), beta * le, c_off,
                 nonfinite);
      }
#else
      float p_light = (last_specular || su.light < 0) ? 0.0f : surface_light_pdf(&s, &su, rh.ray.tfar, wo);
      for (int k = 0; k < GPT_OFFSETS; ++k) {
        float3 le_off = (float3)(0.0f);
        float q_off = 0.0f;
        if (offset_alive(&o[k]) && so[k].light >= 0) {
          le_off = surface_radiance(&s, &so[k], wo_off[k]);
          if (!o[k].last_delta) q_off = surface_light_pdf(&s, &so[k], dist_off[k], wo_off[k]);
        }
        add_bsdf_emission(acc, st->pixel, k, &o[k], p_bsdf, p_light, beta * le, le_off, q_off, nonfinite);
      }
#endif
    }
  }
#endif

  if (path_depth_reached(st, params.path.max_depth)) {
    for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];
    return;
  }

  Bsdf b = surface_bsdf_queued(&s, &su, type);
  Frame frame = frame_from_normal(su.ns);
  float3 wo_l = frame_to_local(&frame, wo);
  PathSampler ps = path_state_sampler_bound(st, params.path.seed, PRIMARY_SAMPLE_NAMES);

  // Next-event estimation: the base samples a light point; offsets reconnect to the same point.
  // A light sample the base cannot use (shading and geometric normals disagree) is no sample at
  // all, also for its offsets: the neighbour's base rejects the mirrored case the same way, which
  // keeps the pairwise weights summing to one.
#if !defined(GDR_GPM)
  int light;
  LightSample ls;
  float3 wi_l;
  if (nee_applies(&s, &b) && nee_sample(&s, &ps, st->depth, &su, &frame, &light, &ls, &wi_l)) {
    float3 f_le = bsdf_eval(&b, wo_l, wi_l) * ls.radiance / ls.pdf;  // per unit throughput
    float3 c_base = beta * f_le;
#if defined(GDR_GBDPT)
    float2 others_x = gbdpt_light_point_others(&s, &b, wo_l, wi_l, su.ng, light, &ls, &base.mis, &mo);
#else
    float p_light = ls.pdf, p_b = ls.delta ? 0.0f : bsdf_pdf(&b, wo_l, wi_l);
#endif
    int base_ray_needed = 0, own_rays = 0;
#if defined(GDR_GBDPT_POWER_PRIMAL)
    float3 cp = checked(gbdpt_primal_light_point(&s, &b, wo_l, wi_l, su.ng, light, &ls, &base.mis) * c_base, nonfinite);
    pend[g * GPT_PEND_COUNT + GPT_PEND_PRIMAL] = (float4)(cp, 0.0f);
    base_ray_needed = max3(cp) > 0.0f;
#endif
    int own_ray_of[GPT_OFFSETS];  // offset k's own shadow ray toward lights[k]
    LightSample lights[GPT_OFFSETS];
    for (int k = 0; k < GPT_OFFSETS; ++k) {
      own_ray_of[k] = 0;
      // The offset's partner under light sampling reconnects to the same light point: the ratio
      // of the pair is its prefix ratio. The offset's vertex: its BSDF bo, its directions wol
      // (toward its previous vertex) and wil (toward its light point lo), its normal ng_o.
      int formed = 0, own_ray = 0;
      float3 c_off = (float3)(0.0f);  // f(y) |J| / p(x), weighted below
      Bsdf bo = b;
      float3 wol = wo_l, wil = wi_l, ng_o = su.ng;
      LightSample lo = ls;
      if (o[k].mode == GPT_MODE_JOINED) {
        formed = 1;
        c_off = vload3(0, o[k].throughput) * f_le;
      } else if (o[k].mode == GPT_MODE_JOINED_RECENT) {
        formed = 1;
        wol = frame_to_local(&frame, wo_off[k]);
        c_off = vload3(0, o[k].throughput) * bsdf_eval(&b, wol, wi_l) * ls.radiance / ls.pdf;
      } else if (o[k].mode == GPT_MODE_TRACE) {
        bo = surface_bsdf(&s, &so[k]);
        if (!bsdf_is_delta(&bo) && light_connect(&s, light, so[k].p, &lo)) {
          Frame fo = frame_from_normal(so[k].ns);
          wol = frame_to_local(&fo, wo_off[k]);
          wil = frame_to_local(&fo, lo.wi);
          ng_o = so[k].ng;
          if (sides_agree(lo.wi, so[k].ng, wil.z)) {
            formed = 1;
            c_off = vload3(0, o[k].throughput) * bsdf_eval(&bo, wol, wil) * lo.radiance / lo.pdf;
          }
        }
      }
      float r = formed ? o[k].ratio : 0.0f;
#if defined(GDR_GBDPT)
      float2 others_y = (float2)(0.0f);
      if (formed) others_y = gbdpt_light_point_others(&s, &bo, wol, wil, ng_o, light, &lo, &o[k].mis, &mo);
      float2 w = gbdpt_pair_weights(others_x, others_y, r, formed);
      float w_base = w.x, w_off = w.y;
#else
      float q_b = (!formed || lo.delta) ? 0.0f : bsdf_pdf(&bo, wol, wil);
      float w_base = gpt_weight(p_light, p_b, r), w_off = gpt_weight(lo.pdf, q_b, r);
#endif
      c_off = c_off * w_off;
      if (o[k].mode == GPT_MODE_TRACE) {
        own_ray = c_off.x > 0.0f || c_off.y > 0.0f || c_off.z > 0.0f;
        if (own_ray) {
          c_off = checked(c_off, nonfinite);
          pend[g * GPT_PEND_COUNT + GPT_PEND_OWN(k)] = (float4)(c_off, 0.0f);
          own_ray_of[k] = 1;
          lights[k] = lo;
          ++own_rays;
        }
      }
      float3 cb = checked(w_base * c_base, nonfinite);
      pend[g * GPT_PEND_COUNT + GPT_PEND_BASE(k)] = (float4)(cb, 0.0f);
      base_ray_needed |= cb.x > 0.0f || cb.y > 0.0f || cb.z > 0.0f;
      float3 co = (float3)(0.0f);
      if (!own_ray && (o[k].mode == GPT_MODE_JOINED || o[k].mode == GPT_MODE_JOINED_RECENT)) {
        co = checked(c_off, nonfinite);
        base_ray_needed |= co.x > 0.0f || co.y > 0.0f || co.z > 0.0f;
      }
      pend[g * GPT_PEND_COUNT + GPT_PEND_JOINED(k)] = (float4)(co, 0.0f);
    }
    for (int k = 0; k < GPT_OFFSETS; ++k) {
      if (own_ray_of[k]) shade_append_shadow(out, so[k].p, so[k].ng, &lights[k], GPT_SHADOW_ID(g, 1 + k));
    }
    if (base_ray_needed) shade_append_shadow(out, su.p, su.ng, &ls, GPT_SHADOW_ID(g, 0));
  }
#endif

#if defined(GDR_GBDPT)
  if (!bsdf_is_delta(&b) && gbdpt_records_at(st->depth, params.path.max_depth)) {
    records[g] = gbdpt_camera_vertex(&s, &rh.hit, wo, beta, &base, is_diffuse(&b, params.shift_threshold), o, so,
                                     wo_off, params.shift_threshold);
    out->connectable = 1;
  }
#endif
#if defined(GDR_GPM)
  // The visible point: the base's first rough vertex, where the group ends. Its offsets are each
  // at a vertex of their own (nothing joins before a rough vertex), recorded as such whatever
  // their roughness (threshold -1); whether they can merge there the merge decides.
  if (!bsdf_is_delta(&b)) {
    if (gpm_merges_at(st->depth, params.path.max_depth)) {
      records[g] = gbdpt_camera_vertex(&s, &rh.hit, wo, beta, &base, 1, o, so, wo_off, -1.0f);
      out->connectable = 1;
    }
    for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];
    return;
  }
#endif

  // The base's BSDF sample; Russian roulette is decided by the base.
  BsdfSample bs;
  float3 wi;
  float rr;
  if (path_continue(st, &ps, params.path.rr_depth, &b, &frame, su.ng, wo_l, &beta, &bs, &wi, &rr) != PATH_CONTINUES) {
    for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];
    return;
  }

  // Offsets that share this vertex follow the base's sample directly.
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (o[k].mode != GPT_MODE_JOINED && o[k].mode != GPT_MODE_JOINED_RECENT) continue;
    ShiftPrefix pre = offset_prefix(&o[k]);
    int reason = shift_follow_base(&b, &frame, o[k].mode == GPT_MODE_JOINED_RECENT, wo_off[k], &bs, rr, &pre);
    if (reason) {
      kill_offset(&o[k], stats, reason);
    } else {
      offset_keep(&o[k], &pre);
#if defined(GDR_GBDPT)
      float3 wr = o[k].mode == GPT_MODE_JOINED_RECENT ? frame_to_local(&frame, wo_off[k]) : wo_l;
      gbdpt_sums_scatter(o[k].last_delta, o[k].last_pdf, bsdf_pdf(&b, bs.wi, wr), fabs(dot(su.ng, wi)), &mo, &o[k].mis);
#endif
      o[k].mode = GPT_MODE_JOINED;
    }
  }
#if defined(GDR_GBDPT)
  gbdpt_sums_scatter(bs.delta, bs.pdf, bsdf_pdf(&b, bs.wi, wo_l), fabs(dot(su.ng, wi)), &mo, &base.mis);
#endif
  for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];

  path_advance(st, beta, &bs);
  base.prim = rh.hit.primID;
  base.b1 = rh.hit.u;
  base.b2 = rh.hit.v;
  base.sample_delta = bs.delta;
  base.sample_transmitted = bs.transmitted;
  base.sample_eta = bs.eta;
  vstore3(wi, 0, base.wi);
  vstore3(wo, 0, base.wo);
  base.rr_prob = rr;
  bases[g] = base;
  out->next = 1;
  // Once every offset has joined the base or died (on diffuse scenes from the second vertex on)
  // the shift step has nothing to do for the group (an offset never goes back to being traced).
  for (int k = 0; k < GPT_OFFSETS; ++k) out->shift |= o[k].mode == GPT_MODE_TRACE || o[k].mode == GPT_MODE_MANIFOLD;
  out->next_p = su.p;
  out->next_ng = su.ng;
  out->next_wi = wi;
}

// The base hits' material queues (path/material_queues.h): each entry's key, the BSDF type of
// its base's hit; a miss is shaded here (the escaped paths' emission: nothing to append).
__kernel void gpt_route(GdrGptParams params, uint count, __global const GdrRayHit* base_in, __global uint* keys,
                        __global GptBaseState* bases, __global GptOffsetState* offsets, __global float4* acc,
                        __global float4* pend, __global GbdptCameraVertex* records, __global uint* counters,
                        PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  if (base_in[q].hit.geomID != GDR_INVALID_ID) {
    SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
    keys[q] = material_queue_key(&s, base_in[q].hit.primID);
    return;
  }
  keys[q] = MATERIAL_QUEUE_NONE;
  if (path_no_segments(params.path.max_depth)) return;
  GptShadeAppend out;
  out.shadows = out.connectable = out.next = out.shift = 0u;
  gpt_shade_group(params, q, -1, base_in, bases, offsets, acc, pend, records, counter_shard(counters), &out,
                  PRIMARY_SAMPLE_NAMES, SCENE_DATA_NAMES);
}

// gpt_shade_<material>: the shade step of the groups whose base hit that material, the queue's
// entries sorted[first, first + count) (with `direct`, the entries [0, count) themselves, misses
// included: the scene has one material type); gpt_shade: the whole queue unrouted, every type
// (`direct`). Each work-group appends its rays and records together (group_reserve).
// shift_groups lists the base_out entries of the groups the shift step takes.
#define GPT_SHADE_KERNEL(kernel, TYPE)                                                                               \
  __kernel void kernel(GdrGptParams params, uint count, uint first, int direct,                                      \
                       __global const uint* sorted, __global const GdrRayHit* base_in,                               \
                       __global GdrRayHit* base_out, __global uint* shift_groups,                                    \
                       __global GdrRay* shadow_rays, __global GptBaseState* bases,                                   \
                       __global GptOffsetState* offsets, __global float4* acc, __global float4* pend,                \
                       __global GbdptCameraVertex* records, __global uint* connectable,                              \
                       __global uint* counters, PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {                              \
    __local uint scratch[GROUP_RESERVE_SCRATCH];                                                                     \
    uint i = get_global_id(0), q = 0;                                                                                \
    GptShadeAppend out;                                                                                              \
    out.shadows = out.connectable = out.next = out.shift = 0u;                                                       \
    if (i < count && !path_no_segments(params.path.max_depth)) {                                                     \
      q = direct ? i : sorted[first + i];                                                                            \
      gpt_shade_group(params, q, TYPE, base_in, bases, offsets, acc, pend, records, counter_shard(counters), &out,    \
                      PRIMARY_SAMPLE_NAMES, SCENE_DATA_NAMES);                                                       \
    }                                                                                                                \
    const uint which[4] = {GPT_COUNTER_SHADOW_RAYS, GPT_COUNTER_CONNECTABLE, GPT_COUNTER_BASE_RAYS,                  \
                           GPT_COUNTER_SHIFT_GROUPS};                                                                \
    uint slot[4] = {out.shadows, out.connectable, out.next, out.shift};                                              \
    group_reserve(scratch, counters, which, 4, slot);                                                                \
    if (out.shadows == 0u && out.connectable == 0u && out.next == 0u) return;                                        \
    uint g = base_in[q].ray.id;                                                                                      \
    for (uint j = 0; j < out.shadows; ++j) {                                                                         \
      write_light_ray(&shadow_rays[slot[0] + j], out.shadow_p[j], out.shadow_ng[j], out.shadow_wi[j],                \
                      out.shadow_dist[j], out.shadow_id[j]);                                                         \
    }                                                                                                                \
    if (out.connectable) connectable[slot[1]] = g;                                                                   \
    if (out.next) spawn_ray(&base_out[slot[2]], out.next_p, out.next_ng, out.next_wi, g);                            \
    if (out.shift) shift_groups[slot[3]] = slot[2];                                                                  \
  }
#define GPT_SHADE_QUEUE(name, TYPE) GPT_SHADE_KERNEL(gpt_shade_##name, TYPE)
GDR_MATERIAL_QUEUES(GPT_SHADE_QUEUE)
GPT_SHADE_KERNEL(gpt_shade, -1)

// Adds the next-event contributions whose shadow rays Embree found unoccluded.
__kernel void gpt_shadow(uint count, __global const GdrRay* shadow_rays, __global const float4* pend,
                         __global const GptBaseState* bases, __global float4* acc) {
  uint i = get_global_id(0);
  if (i >= count) return;
  GdrRay r = shadow_rays[i];
  if (!shadow_unoccluded(r.tfar)) return;
  uint g = r.id / 8u, kind = r.id % 8u;
  uint pixel = bases[g].path.pixel;
  // The base's ray (kind 0) and offset k's own ray both add to ACC_OFFSET(k) without atomics:
  // safe because an offset is either joined (its share rides on the base's ray, PEND_JOINED) or
  // traced (its own ray, PEND_OWN), never both, and acc_add skips the zero entries.
  if (kind == 0u) {
    for (int k = 0; k < GPT_OFFSETS; ++k) {
      acc_add(acc, pixel, GPT_ACC_BASE(k), pend[g * GPT_PEND_COUNT + GPT_PEND_BASE(k)].xyz);
      acc_add(acc, pixel, GPT_ACC_OFFSET(k), pend[g * GPT_PEND_COUNT + GPT_PEND_JOINED(k)].xyz);
    }
#if defined(GDR_GBDPT_POWER_PRIMAL)
    acc_add(acc, pixel, GPT_ACC_PRIMAL, pend[g * GPT_PEND_COUNT + GPT_PEND_PRIMAL].xyz);  // zero elsewhere
#endif
  } else {
    int k = (int)kind - 1;
    acc_add(acc, pixel, GPT_ACC_OFFSET(k), pend[g * GPT_PEND_COUNT + GPT_PEND_OWN(k)].xyz);
  }
}
