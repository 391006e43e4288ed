// The state a path carries from bounce to bounce (GdrPathState, shared/pt_types.h): its start at
// the camera, the sampler of its random numbers, the depth limit and the step to the next vertex.
#pragma once
#include "bsdf/bsdf.h"
#include "sampling/path_sampler.h"
#include "shared/pt_types.h"

inline GdrPathState path_start(uint pixel, uint sample) {
  GdrPathState st;
  st.throughput[0] = st.throughput[1] = st.throughput[2] = 1.0f;
  st.bsdf_pdf = 0.0f;
  st.pixel = pixel;
  st.sample = sample;
  st.depth = 0;
  st.flags = PATH_FLAG_SPECULAR;  // emission seen from the camera is never MIS-weighted
  return st;
}

inline PathSampler path_state_sampler(const GdrPathState* st, uint seed) {
  return path_sampler(seed, st->pixel, st->sample);
}

// The same in a kernel that declares PRIMARY_SAMPLE_ARGS (`pixel` is then the chain).
inline PathSampler path_state_sampler_bound(const GdrPathState* st, uint seed, __global const float* numbers,
                                            GdrPrimaryLayout layout) {
  return path_sampler_bound(seed, st->pixel, st->sample, numbers, layout);
}

// Mitsuba's max_depth 0: not even the camera segment counts, so nothing is seen.
inline int path_no_segments(int max_depth) { return max_depth == 0; }

// Mitsuba's max_depth counts segments: the next vertex would make depth + 2 of them (< 0:
// unbounded).
inline int path_depth_reached(const GdrPathState* st, int max_depth) {
  return max_depth > 0 && st->depth + 2 > max_depth;
}

// The path moves on by BSDF sample bs with throughput beta.
inline void path_advance(GdrPathState* st, float3 beta, const BsdfSample* bs) {
  st->depth += 1;
  st->bsdf_pdf = bs->pdf;
  st->flags = bs->delta ? PATH_FLAG_SPECULAR : 0;
  vstore3(beta, 0, st->throughput);
}
