// One step of a batch of Markov chains in primary sample space, as two kernels around the
// caller's evaluation of the target f at the proposals:
//   mlt_propose  mutates every chain's state into a proposal (a small or a large step);
//   (caller)     evaluates f at each proposal into f_proposed;
//   mlt_accept   accepts a proposal with probability a = min(1, f(y) / f(x)) and returns the
//                expected-value weights (1 - a for the current state, a for the proposal) that
//                let the caller splat both (Veach's use of rejected samples).
// mlt_seed starts chains at states that large steps drew before (a bootstrap's picks).
#pragma once
#include "mlt/mutation.h"

// The dimensions the target reads at a state whose first dimension is u0 (GdrMltParams.lengths).
inline uint mlt_dims_read(const GdrMltParams* p, float u0) {
  if (p->lengths == 0u) return p->dims;
  uint n = 1u + min((uint)(u0 * (float)p->lengths), p->lengths - 1u);
  return min(p->dims, 4u * (uint)GDR_PRIMARY_BLOCKS(n));
}

// Dimensions [d, d + 4) of chain c in a state buffer (those past dims read as 0, never written).
inline float4 mlt_load_block(const GdrMltParams* p, __global const float* states, uint c, uint d) {
  float4 x = (float4)(0.0f);
  size_t i = (size_t)d * p->chains + c, n = p->chains;
  x.x = states[i];
  if (d + 1 < p->dims) x.y = states[i + n];
  if (d + 2 < p->dims) x.z = states[i + 2 * n];
  if (d + 3 < p->dims) x.w = states[i + 3 * n];
  return x;
}

inline void mlt_store_block(const GdrMltParams* p, __global float* states, uint c, uint d, float4 x) {
  size_t i = (size_t)d * p->chains + c, n = p->chains;
  states[i] = x.x;
  if (d + 1 < p->dims) states[i + n] = x.y;
  if (d + 2 < p->dims) states[i + 2 * n] = x.z;
  if (d + 3 < p->dims) states[i + 3 * n] = x.w;
}

// A step where the target reads fewer dimensions than the state holds works on the dimensions the
// proposal reads alone: a state is the dimensions its path reads (GdrMltParams.lengths: those of
// the length its first dimension picks; reported: the leading dimensions the caller found it
// read, `held`), and the others are not part of it (their stale values are never read). A large
// step draws the proposal's dimensions fresh; a small step moves those both states read and draws
// the ones only the proposal reads fresh (uniform, density 1: the move back drops them), so both
// steps are symmetric between the two states and the acceptance stays min(1, f(y) / f(x))
// (Green's reversible jumps, with a Jacobian of 1). Reported, the proposal's reach is known only
// once it is traced: every dimension past the current state's is drawn fresh.
__kernel void mlt_propose(GdrMltParams p, __global const float* current, __global float* proposed,
                          __global const uint* held_dims, __global uint* counters) {
  uint c = get_global_id(0);
  if (c >= p.chains) return;
  int is_large = mlt_control(&p, c).large;
  atomic_inc(&counters[is_large ? MLT_COUNTER_LARGE_STEPS : MLT_COUNTER_SMALL_STEPS]);
  float4 x = mlt_load_block(&p, current, c, 0);
  float4 y = mlt_mutate_block(&p, c, 0, is_large, x);
  mlt_store_block(&p, proposed, c, 0, y);
  uint held = p.reported ? held_dims[c] : mlt_dims_read(&p, x.x), dims = mlt_dims_read(&p, y.x);
  for (uint d = 4; d < dims; d += 4) {
    int fresh = is_large || d >= held;
    float4 from = fresh ? (float4)(0.0f) : mlt_load_block(&p, current, c, d);
    mlt_store_block(&p, proposed, c, d, mlt_mutate_block(&p, c, d / 4, fresh, from));
  }
}

// large_targets[c] sums f over chain c's large-step proposals and counts them: fresh uniform
// states, whose mean target estimates the target's integral (Kelemen et al.'s normalization).
__kernel void mlt_accept(GdrMltParams p, __global float* current, __global const float* proposed,
                         __global float* f_current, __global const float* f_proposed, __global float2* weights,
                         __global float2* large_targets, __global uint* held_dims, __global const uint* read_dims,
                         __global uint* counters) {
  uint c = get_global_id(0);
  if (c >= p.chains) return;
  float fx = f_current[c], fy = f_proposed[c];
  // A proposal with a non-finite or negative target is never taken; a current state with f = 0
  // (a chain seeded where nothing contributes) takes any proposal.
  int usable = fy > 0.0f && isfinite(fy);
  float a = !usable ? 0.0f : fx > 0.0f ? fmin(1.0f, fy / fx) : 1.0f;
  weights[c] = (float2)(1.0f - a, a);
  MltControl k = mlt_control(&p, c);
  if (k.large) large_targets[c] += (float2)(usable ? fy : 0.0f, 1.0f);
  if (!(k.accept < a)) return;
  uint dims = p.reported ? min(p.dims, read_dims[c]) : mlt_dims_read(&p, proposed[c]);
  if (p.reported) held_dims[c] = dims;
  for (uint d = 0; d < dims; ++d) {
    size_t i = (size_t)d * p.chains + c;
    current[i] = proposed[i];
  }
  f_current[c] = fy;
  atomic_inc(&counters[k.large ? MLT_COUNTER_LARGE_ACCEPTED : MLT_COUNTER_SMALL_ACCEPTED]);
}

// Writes into chain c of `states` every dimension of the large step that chain `from` took at
// `iteration` under `seed`.
inline void mlt_store_large_step(const GdrMltParams* p, __global float* states, uint c, uint seed, uint from,
                                 uint iteration) {
  for (uint d = 0; d < p->dims; d += 4) mlt_store_block(p, states, c, d, mlt_large_block(seed, from, iteration, d / 4));
}

// Chain c starts at the state that the large step of chain picks[c].x at iteration picks[c].y drew.
__kernel void mlt_seed(GdrMltParams p, __global const uint2* picks, __global float* current) {
  uint c = get_global_id(0);
  if (c >= p.chains) return;
  mlt_store_large_step(&p, current, c, p.seed, picks[c].x, picks[c].y);
}
