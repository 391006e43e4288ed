// An offset that reached the base's vertex x_k (by reconnection) follows the base's BSDF sample
// there: one that shares all the base's vertices takes the sample as it is; one that has just
// joined arrived from its own previous vertex, so the base's direction is evaluated from its own
// incoming direction.
#pragma once
#include "bsdf/bsdf.h"
#include "shared/gpt_types.h"
#include "shift/prefix.h"

// wo_off: the joined offset's direction toward its previous vertex (world), where `recent`.
// Returns 0, or the GPT_COUNTER_FAIL_* reason the offset cannot follow.
inline int shift_follow_base(const Bsdf* b, const Frame* frame, int recent, float3 wo_off, const BsdfSample* bs,
                             float rr, ShiftPrefix* o) {
  if (!recent) {
    o->throughput *= bs->weight;
    o->last_pdf = bs->pdf;
  } else {
    float3 wr = frame_to_local(frame, wo_off);
    float3 f = bsdf_eval(b, wr, bs->wi);
    float p = bsdf_pdf(b, wr, bs->wi);
    if (bs->delta || !(p > 0.0f) || max3(f) <= 0.0f) return GPT_COUNTER_FAIL_ZERO;
    o->throughput *= f / bs->pdf;
    o->ratio *= p / bs->pdf;
    o->last_pdf = p;
  }
  o->last_delta = bs->delta;
  if (rr < 1.0f) shift_roulette(o, rr);
  if (!shift_prefix_finite(o)) return GPT_COUNTER_FAIL_NONFINITE;
  return 0;
}
