// The Markov-chain kernels (kernels/mlt/chains.h) and an analytic target on [0, 1)^2 for the
// host tests: a floor, a narrow peak and a bright block with a sharp edge.
#include "mlt/chains.h"

inline float mlt_test_f(float u, float v) {
  float du = u - 0.3f, dv = v - 0.6f;
  float f = 0.2f + exp(-(du * du + dv * dv) / (2.0f * 0.08f * 0.08f));
  if (u > 0.7f && v < 0.4f) f += 1.5f;
  return f;
}

__kernel void mlt_test_target(uint chains, __global const float* states, __global float* f) {
  uint c = get_global_id(0);
  if (c >= chains) return;
  f[c] = mlt_test_f(states[c], states[chains + c]);
}
