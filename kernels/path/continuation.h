// Continuation by BSDF sampling with Russian roulette, from the BSDF block of the path's random
// numbers (xyz the sample, w the roulette).
#pragma once
#include "bsdf/bsdf.h"
#include "path/path_state.h"
#include "path/sides.h"

#define PATH_ENDS 0
#define PATH_CONTINUES 1
#define PATH_ENDS_NONFINITE 2  // the throughput overflowed (the caller decides whether to count it)

// Samples the BSDF b at the vertex of st (geometric normal ng, frame, wo_local) and applies the
// sample and Russian roulette after rr_depth bounces to *beta. Gives the sample, its world
// direction *wi and the survival probability *rr (1 without roulette).
inline int path_continue(const GdrPathState* st, const PathSampler* ps, int rr_depth, const Bsdf* b,
                         const Frame* frame, float3 ng, float3 wo_local, float3* beta, BsdfSample* bs, float3* wi,
                         float* rr) {
  float4 ub = sampler_block(ps, RNG_BLOCK_BSDF(st->depth));
  if (!bsdf_sample(b, wo_local, ub.xyz, bs)) return PATH_ENDS;
  *wi = frame_to_world(frame, bs->wi);
  if (!sides_agree(*wi, ng, bs->wi.z)) return PATH_ENDS;
  float3 t = *beta * bs->weight;
  if (!is_finite3(t)) return PATH_ENDS_NONFINITE;
  if (!(max3(t) > 0.0f)) return PATH_ENDS;
  *rr = 1.0f;
  if (st->depth + 1 >= rr_depth) {
    *rr = fmin(max3(t), 0.95f);
    if (!(ub.w < *rr)) return PATH_ENDS;
    t /= *rr;
  }
  *beta = t;
  return PATH_CONTINUES;
}
