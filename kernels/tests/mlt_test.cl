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

// A target over states of bidirectional paths of one or two segments (GdrMltParams.lengths = 2,
// 24 dimensions): dimension 0 picks the length; both lengths read dimension 5, and only length 2
// reads dimension 20 (past length 1's 16 dimensions), where it has a peak.
inline float mlt_test_lengths_f(float u0, float u5, float u20, int read_u20) {
  if (!read_u20) return 0.5f * (1.0f + u5);
  float d = u20 - 0.7f;
  return (1.0f + u5) * (1.0f + 3.0f * exp(-d * d / (2.0f * 0.05f * 0.05f)));
}

__kernel void mlt_test_lengths_target(uint chains, __global const float* states, __global float* f) {
  uint c = get_global_id(0);
  if (c >= chains) return;
  float u0 = states[c];
  int two = u0 >= 0.5f;
  f[c] = mlt_test_lengths_f(u0, states[5 * chains + c], two ? states[20 * chains + c] : 0.0f, two);
}

// The same target over states that report what they read (GdrMltParams.reported): dimension 0
// decides whether dimension 20 is read, and the state reports 16 or 24 leading dimensions.
__kernel void mlt_test_reported_target(uint chains, __global const float* states, __global float* f,
                                       __global uint* read) {
  uint c = get_global_id(0);
  if (c >= chains) return;
  float u0 = states[c];
  int two = u0 >= 0.5f;
  f[c] = mlt_test_lengths_f(u0, states[5 * chains + c], two ? states[20 * chains + c] : 0.0f, two);
  read[c] = two ? 24u : 16u;
}
