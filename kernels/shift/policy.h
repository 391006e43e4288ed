// The shift policy: how an offset path at its own vertex y follows the base's scattering at x_k
// toward x_{k+1}. Random-number replay when asked for; otherwise a delta lobe is copied, a pair
// of rough vertices reconnects to x_{k+1} (or copies the direction where the base escaped), and
// the rest copies the half vector.
#pragma once
#include "path/scene.h"
#include "path/sides.h"
#include "shared/gpt_types.h"
#include "shift/delta_lobe.h"
#include "shift/half_vector.h"
#include "shift/prefix.h"
#include "shift/reconnect.h"
#include "shift/replay.h"

// Rough enough to reconnect (shared/material_class.h; threshold: GdrGptParams.shift_threshold).
inline int is_diffuse(const Bsdf* b, float threshold) { return material_is_diffuse(bsdf_roughness(b), threshold); }

// The base's scattering at x_k.
typedef struct ShiftBase {
  float3 p;         // x_k
  float3 wo, wi;    // toward the previous and the next vertex, in x_k's shading frame
  float3 wi_world;
  float pdf;        // of wi (solid angle; a delta lobe's selection probability)
  float eta;        // relative IOR across x_k (wi side / wo side)
  float rr_prob;    // Russian-roulette survival probability applied at x_k (1: none)
  int delta;        // the sample took a delta lobe
  int transmitted;
  int diffuse;      // is_diffuse at x_k
  float4 u;         // the random numbers of the sample
} ShiftBase;

// The base's next vertex x_{k+1}.
typedef struct ShiftNext {
  int hit;      // 0: the base escaped
  int diffuse;  // is_diffuse at x_{k+1}
  float3 p, ng;
} ShiftNext;

// The offset's vertex y.
typedef struct ShiftVertex {
  Surface su;
  Bsdf b;
  Frame frame;
  float3 wo;    // toward its previous vertex, in its shading frame
  int diffuse;  // is_diffuse at y
} ShiftVertex;

inline ShiftVertex shift_vertex_at(const SceneData* s, uint prim, float b1, float b2, float3 wo_world,
                                   float threshold) {
  ShiftVertex y;
  y.su = surface_at(s, prim, b1, b2);
  y.b = surface_bsdf(s, &y.su);
  y.frame = frame_from_normal(y.su.ns);
  y.wo = frame_to_local(&y.frame, wo_world);
  y.diffuse = is_diffuse(&y.b, threshold);
  return y;
}

// Shifts the offset's prefix o across y by the policy (shift: GPT_SHIFT_*): its new direction
// *wi_world, *reconnect where it goes straight to x_{k+1} (visibility still to be tested), and
// *glossy_next_only where the offset's next vertex must be glossy (shift_reverses_at).
// Counts each shift taken (GPT_COUNTER_SHIFT_*). Returns 0, or the GPT_COUNTER_FAIL_* reason the
// offset cannot follow.
inline int shift_offset(int shift, const ShiftBase* x, const ShiftNext* next, const ShiftVertex* y,
                        ShiftPrefix* o, float3* wi_world, int* reconnect, int* glossy_next_only,
                        __global uint* counters) {
  int reason = 0;
  *reconnect = 0;
  *glossy_next_only = 0;
  if (shift == GPT_SHIFT_REPLAY) {
    BsdfSample so;
    if (!shift_replay(&y->b, y->wo, x->u, x->delta, &so)) {
      reason = GPT_COUNTER_FAIL_LOBE;
    } else {
      o->throughput *= so.weight;
      o->last_pdf = so.pdf;
      o->last_delta = so.delta;
      *wi_world = frame_to_world(&y->frame, so.wi);
      atomic_inc(&counters[GPT_COUNTER_SHIFT_REPLAY]);
    }
  } else if (x->delta) {
    BsdfSample so;
    if (!bsdf_sample_delta_lobe(&y->b, y->wo, x->transmitted, &so)) {
      reason = x->transmitted ? GPT_COUNTER_FAIL_REFRACTION : GPT_COUNTER_FAIL_LOBE;
    } else {
      o->throughput *= so.weight * (so.pdf / x->pdf);
      o->ratio *= so.pdf / x->pdf;
      o->last_pdf = so.pdf;
      o->last_delta = 1;
      *wi_world = frame_to_world(&y->frame, so.wi);
      atomic_inc(&counters[GPT_COUNTER_SHIFT_DELTA]);
    }
  } else {
    int diffuse_pair = x->diffuse && y->diffuse;
    float3 wiy;
    float jac = 1.0f;
    int ok = 1;
    if (diffuse_pair && next->diffuse) {
      // Reconnect to the base's next vertex.
      float3 d = next->p - y->su.p;
      *wi_world = normalize_or(d, x->wi_world);
      wiy = frame_to_local(&y->frame, *wi_world);
      jac = reconnect_jacobian(x->p, y->su.p, next->p, next->ng);
      // Both paths must reach x_{k+1} from the same side of its surface.
      ok = jac > 0.0f && dot(x->p - next->p, next->ng) * dot(y->su.p - next->p, next->ng) > 0.0f;
      *reconnect = 1;
      if (ok) atomic_inc(&counters[GPT_COUNTER_SHIFT_RECONNECT]);
    } else if (diffuse_pair && !next->hit) {
      // The base escaped: reconnect at infinity, i.e. copy the direction (Jacobian 1).
      *wi_world = x->wi_world;
      wiy = frame_to_local(&y->frame, *wi_world);
      atomic_inc(&counters[GPT_COUNTER_SHIFT_DIRECTION]);
    } else {
      // A diffuse pair copies the half vector only because x_{k+1} is glossy.
      *glossy_next_only = diffuse_pair;
      ok = shift_half_vector(x->wo, x->wi, x->transmitted, x->eta, y->wo, y->b.eta.x, &wiy, &jac);
      if (ok) {
        *wi_world = frame_to_world(&y->frame, wiy);
        atomic_inc(&counters[GPT_COUNTER_SHIFT_HALF_VECTOR]);
      } else {
        reason = x->transmitted ? GPT_COUNTER_FAIL_REFRACTION : GPT_COUNTER_FAIL_ZERO;
      }
    }
    if (ok) {
      float3 f = bsdf_eval(&y->b, y->wo, wiy);
      float p = bsdf_pdf(&y->b, y->wo, wiy);
      if (!(p > 0.0f) || max3(f) <= 0.0f) {
        reason = GPT_COUNTER_FAIL_ZERO;
      } else {
        o->throughput *= f * (jac / x->pdf);
        o->ratio *= p * jac / x->pdf;
        o->last_pdf = p;
        o->last_delta = 0;
      }
    } else if (!reason) {
      reason = GPT_COUNTER_FAIL_ZERO;
    }
  }
  if (!reason && !sides_agree(*wi_world, y->su.ng, dot(*wi_world, y->su.ns))) reason = GPT_COUNTER_FAIL_ZERO;
  if (!reason && x->rr_prob < 1.0f) shift_roulette(o, x->rr_prob);
  if (!reason && !shift_prefix_finite(o)) reason = GPT_COUNTER_FAIL_NONFINITE;
  return reason;
}

// The shift must be its own reverse. An offset that copied the half vector from a pair of
// diffuse vertices (because the base's next vertex is glossy) and then hit a diffuse vertex would,
// taken as a base, be reconnected to that vertex by the reverse shift instead of being shifted
// back to the base: the two are no pair, so the offset fails and its base takes the full weight.
inline int shift_reverses_at(const Bsdf* b_next, float threshold) { return !is_diffuse(b_next, threshold); }
