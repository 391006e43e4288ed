// One step of a batch of Markov chains in primary sample space, as two kernels around the
// caller's evaluation of the target f at the proposals:
//   mlt_propose  mutates every chain's state into a proposal (a small or a large step);
//   (caller)     evaluates f at each proposal into f_proposed;
//   mlt_accept   accepts a proposal with probability a = min(1, f(y) / f(x)) and returns the
//                expected-value weights (1 - a for the current state, a for the proposal) that
//                let the caller splat both (Veach's use of rejected samples).
#pragma once
#include "mlt/mutation.h"

__kernel void mlt_propose(GdrMltParams p, __global const float* current, __global float* proposed,
                          __global uint* counters) {
  uint c = get_global_id(0);
  if (c >= p.chains) return;
  int is_large = mlt_control(&p, c).large;
  atomic_inc(&counters[is_large ? MLT_COUNTER_LARGE_STEPS : MLT_COUNTER_SMALL_STEPS]);
  for (uint d = 0; d < p.dims; d += 2) {
    size_t i = (size_t)d * p.chains + c, j = i + p.chains;
    int pair = d + 1 < p.dims;  // an odd last dimension has no partner
    float2 y = mlt_mutate_pair(&p, c, d / 2, is_large, (float2)(current[i], pair ? current[j] : 0.0f));
    proposed[i] = y.x;
    if (pair) proposed[j] = y.y;
  }
}

__kernel void mlt_accept(GdrMltParams p, __global float* current, __global const float* proposed,
                         __global float* f_current, __global const float* f_proposed, __global float2* weights,
                         __global uint* counters) {
  uint c = get_global_id(0);
  if (c >= p.chains) return;
  float fx = f_current[c], fy = f_proposed[c];
  // A proposal with a non-finite or negative target is never taken; a current state with f = 0
  // (a chain seeded where nothing contributes) takes any proposal.
  float a = !(fy > 0.0f) || !isfinite(fy) ? 0.0f : fx > 0.0f ? fmin(1.0f, fy / fx) : 1.0f;
  weights[c] = (float2)(1.0f - a, a);
  MltControl k = mlt_control(&p, c);
  if (!(k.accept < a)) return;
  for (uint d = 0; d < p.dims; ++d) {
    size_t i = (size_t)d * p.chains + c;
    current[i] = proposed[i];
  }
  f_current[c] = fy;
  atomic_inc(&counters[k.large ? MLT_COUNTER_LARGE_ACCEPTED : MLT_COUNTER_SMALL_ACCEPTED]);
}
