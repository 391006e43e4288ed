// Fills a buffer with the engine's random numbers: used by the tests (uniformity, determinism
// across devices) and the RNG microbenchmark.
#include "core/rng.h"

// out[i] for i < count: dimension (i % dims) of sample (i / dims) of `pixel`.
__kernel void rng_fill(__global float* out, uint count, uint seed, uint pixel, uint dims) {
  uint i = get_global_id(0);
  if (i >= count) return;
  out[i] = rng_uniform(seed, pixel, i / dims, i % dims);
}
