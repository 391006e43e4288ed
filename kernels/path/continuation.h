// Continuation by BSDF sampling with Russian roulette, from a BSDF block of the path's random
// numbers (xyz the sample, w the roulette), for camera paths and light subpaths.
#pragma once
#include "bsdf/transport.h"
#include "path/path_state.h"
#include "path/sides.h"

#define PATH_ENDS 0
#define PATH_CONTINUES 1
#define PATH_ENDS_NONFINITE 2  // the throughput overflowed (the caller decides whether to count it)

// Samples the BSDF b at a vertex `depth` bounces into its path (geometric normal ng, frame,
// wo_local) from block `block` of the path's numbers in transport `mode` (bsdf/transport.h;
// importance transport also applies the shading-normal correction), and applies the sample and
// Russian roulette after rr_depth bounces to *beta. Roulette survives with the largest
// throughput component over rr_scale: 1 for camera paths, whose throughput starts at 1; a light
// subpath's first throughput, so that its roulette does not depend on the lights' units. Gives
// the sample, its world direction *wi and the survival probability *rr (1 without roulette).
inline int path_continue_transport(int depth, const PathSampler* ps, uint block, int rr_depth, float rr_scale,
                                   int mode, const Bsdf* b, const Frame* frame, float3 ng, float3 wo_local,
                                   float3* beta, BsdfSample* bs, float3* wi, float* rr) {
  float4 ub = sampler_block(ps, block);
  if (!bsdf_sample_transport(b, wo_local, ub.xyz, mode, bs)) return PATH_ENDS;
  *wi = frame_to_world(frame, bs->wi);
  float3 w = bs->weight;
  if (mode == TRANSPORT_IMPORTANCE) {
    // The side check applies to the light-side direction (here wo), as camera paths apply it to
    // theirs (wi): both directions of tracing then accept the same paths.
    float3 wo = frame_to_world(frame, wo_local);
    if (!sides_agree(wo, ng, wo_local.z)) return PATH_ENDS;
    w *= shading_normal_correction(wo, *wi, ng, wo_local.z, bs->wi.z);
  } else if (!sides_agree(*wi, ng, bs->wi.z)) {
    return PATH_ENDS;
  }
  float3 t = *beta * w;
  if (!is_finite3(t)) return PATH_ENDS_NONFINITE;
  if (!(max3(t) > 0.0f)) return PATH_ENDS;
  *rr = 1.0f;
  if (depth + 1 >= rr_depth) {
    *rr = fmin(max3(t) / rr_scale, 0.95f);
    if (!(ub.w < *rr)) return PATH_ENDS;
    t /= *rr;
  }
  *beta = t;
  return PATH_CONTINUES;
}

// A camera path's continuation (radiance transport, the BSDF block of its depth).
inline int path_continue(const GdrPathState* st, const PathSampler* ps, int rr_depth, const Bsdf* b,
                         const Frame* frame, float3 ng, float3 wo_local, float3* beta, BsdfSample* bs, float3* wi,
                         float* rr) {
  return path_continue_transport(st->depth, ps, RNG_BLOCK_BSDF(st->depth), rr_depth, 1.0f, TRANSPORT_RADIANCE, b,
                                 frame, ng, wo_local, beta, bs, wi, rr);
}
