// G-PT shift step: with the base's next vertex known, every traced offset follows the base's
// scattering at its own vertex (reconnection, half-vector copy, delta-lobe copy or replay).
#pragma once
#include "core/rng.h"
#include "gpt/common.h"
#include "gpt/shift.h"

// The base's next vertex x_{k+1} is known: every traced offset shifts its outgoing direction.
__kernel void gpt_shift(GdrGptParams params, uint count, __global const GdrRayHit* base_rays,
                        __global GdrRayHit* offset_rays, __global GdrRay* reconnect_rays,
                        __global const GptBaseState* bases, __global GptOffsetState* offsets,
                        __global uint* counters, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  SceneData s = gpt_scene(&params, SCENE_DATA_NAMES);
  GdrRayHit rh = base_rays[q];
  uint g = rh.ray.id;
  GptBaseState base = bases[g];
  Surface sx = surface_at(&s, base.prim, base.b1, base.b2);
  Bsdf bx = surface_bsdf(&s, &sx);
  Frame fx = frame_from_normal(sx.ns);
  float3 wo_l = frame_to_local(&fx, vload3(0, base.wo));
  float3 wi_w = vload3(0, base.wi);
  float3 wi_l = frame_to_local(&fx, wi_w);
  float p_base = base.bsdf_pdf;
  int next_hit = rh.hit.geomID != GDR_INVALID_ID;
  float4 ub = rng_block(params.path.seed, base.pixel, base.sample, RNG_BLOCK_BSDF(base.depth - 1));
  float thr = params.shift_threshold;
  // The base's next vertex, shared by the four offsets' reconnection decisions.
  Surface sn = sx;
  int diffuse_next = 0;
  if (next_hit) {
    sn = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
    Bsdf bn = surface_bsdf(&s, &sn);
    diffuse_next = is_diffuse(&bn, thr);
  }

  for (int k = 0; k < GPT_OFFSETS; ++k) {
    __global GptOffsetState* og = &offsets[g * GPT_OFFSETS + k];
    if (og->mode != GPT_MODE_TRACE) continue;
    GptOffsetState o = *og;
    Surface sy = surface_at(&s, o.prim, o.b1, o.b2);
    Bsdf by = surface_bsdf(&s, &sy);
    Frame fy = frame_from_normal(sy.ns);
    float3 woy = frame_to_local(&fy, -vload3(0, o.dir));
    float3 t = vload3(0, o.throughput);
    float3 wiy_w;  // the offset's new direction (world)
    int reconnect = 0;
    int reason = 0;

    if (params.shift == GPT_SHIFT_REPLAY) {
      BsdfSample so;
      if (!bsdf_sample(&by, woy, ub.xyz, &so) || so.delta != base.sample_delta) {
        reason = GPT_COUNTER_FAIL_LOBE;
      } else {
        // Same random numbers: the path-space Jacobian is p(x)/p(y), so f(y)|J|/p(x) = f/p of
        // the offset's own sample and the pdf ratio does not change.
        t *= so.weight;
        o.last_pdf = so.pdf;
        o.last_delta = so.delta;
        wiy_w = frame_to_world(&fy, so.wi);
        atomic_inc(&counters[GPT_COUNTER_SHIFT_REPLAY]);
      }
    } else if (base.sample_delta) {
      BsdfSample so;
      if (!bsdf_sample_delta_lobe(&by, woy, base.sample_transmitted, &so)) {
        reason = base.sample_transmitted ? GPT_COUNTER_FAIL_REFRACTION : GPT_COUNTER_FAIL_LOBE;
      } else {
        t *= so.weight * (so.pdf / p_base);
        o.ratio *= so.pdf / p_base;
        o.last_pdf = so.pdf;
        o.last_delta = 1;
        wiy_w = frame_to_world(&fy, so.wi);
        atomic_inc(&counters[GPT_COUNTER_SHIFT_DELTA]);
      }
    } else {
      int diffuse_pair = is_diffuse(&bx, thr) && is_diffuse(&by, thr);
      float3 wiy;
      float jac = 1.0f;
      int ok = 1;
      if (diffuse_pair && diffuse_next) {
        // Reconnect to the base's next vertex.
        float3 d = sn.p - sy.p;
        wiy_w = normalize_or(d, wi_w);
        wiy = frame_to_local(&fy, wiy_w);
        jac = reconnect_jacobian(sx.p, sy.p, sn.p, sn.ng);
        // Both paths must reach x_{k+1} from the same side of its surface.
        ok = jac > 0.0f && dot(sx.p - sn.p, sn.ng) * dot(sy.p - sn.p, sn.ng) > 0.0f;
        reconnect = 1;
        if (ok) atomic_inc(&counters[GPT_COUNTER_SHIFT_RECONNECT]);
      } else if (diffuse_pair && !next_hit) {
        // The base escaped: reconnect at infinity, i.e. copy the direction (Jacobian 1).
        wiy_w = wi_w;
        wiy = frame_to_local(&fy, wiy_w);
        atomic_inc(&counters[GPT_COUNTER_SHIFT_DIRECTION]);
      } else {
        ok = shift_half_vector(wo_l, wi_l, base.sample_transmitted, base.sample_eta, woy, by.eta.x, &wiy, &jac);
        if (ok) {
          wiy_w = frame_to_world(&fy, wiy);
          atomic_inc(&counters[GPT_COUNTER_SHIFT_HALF_VECTOR]);
        } else {
          reason = base.sample_transmitted ? GPT_COUNTER_FAIL_REFRACTION : GPT_COUNTER_FAIL_ZERO;
        }
      }
      if (ok) {
        float3 f = bsdf_eval(&by, woy, wiy);
        float p = bsdf_pdf(&by, woy, wiy);
        if (!(p > 0.0f) || max3(f) <= 0.0f) {
          reason = GPT_COUNTER_FAIL_ZERO;
        } else {
          t *= f * (jac / p_base);
          o.ratio *= p * jac / p_base;
          o.last_pdf = p;
          o.last_delta = 0;
        }
      } else if (!reason) {
        reason = GPT_COUNTER_FAIL_ZERO;
      }
    }
    if (!reason && !(dot(wiy_w, sy.ng) * dot(wiy_w, sy.ns) > 0.0f)) reason = GPT_COUNTER_FAIL_ZERO;
    if (!reason && base.rr_prob < 1.0f) {
      // The offset's own-base Russian roulette would have used its own throughput.
      o.ratio *= fmin(max3(t / o.ratio), 0.95f) / base.rr_prob;
      t /= base.rr_prob;
    }
    if (!reason && (!is_finite3(t) || !isfinite(o.ratio))) reason = GPT_COUNTER_FAIL_NONFINITE;
    if (reason) {
      kill_offset(&o, counters, reason);
      *og = o;
      continue;
    }
    vstore3(t, 0, o.throughput);
    vstore3(sy.p, 0, o.prev_pos);
    vstore3(wiy_w, 0, o.dir);
    uint id = g * GPT_OFFSETS + (uint)k;
    if (reconnect) {
      o.mode = GPT_MODE_RECONNECTING;
      o.visible = 0;
      uint r = atomic_inc(&counters[GPT_COUNTER_RECONNECT_RAYS]);
      write_segment_ray(&reconnect_rays[r], sy.p, sy.ng, sn.p, id);
    } else {
      uint r = atomic_inc(&counters[GPT_COUNTER_OFFSET_RAYS]);
      write_ray_hit(&offset_rays[r], offset_ray_origin(sy.p, dot(wiy_w, sy.ng) > 0.0f ? sy.ng : -sy.ng), wiy_w, 0.0f,
                    INFINITY, id);
    }
    *og = o;
  }
}
