// What an offset path has built so far, as the shifts update it, and the base's Russian roulette
// carried over to it.
#pragma once
#include "core/geometry.h"

typedef struct ShiftPrefix {
  float3 throughput;  // f(y) |J| / p(x)
  float ratio;        // p(y) |J| / p(x) (MIS between the two directions)
  float last_pdf;     // the offset's own solid-angle pdf of its last direction
  int last_delta;     // its last direction left a delta lobe
} ShiftPrefix;

// The base survived Russian roulette with probability rr < 1: the offset's own base would have
// used its own throughput.
inline void shift_roulette(ShiftPrefix* o, float rr) {
  o->ratio *= fmin(max3(o->throughput / o->ratio), 0.95f) / rr;
  o->throughput /= rr;
}

inline int shift_prefix_finite(const ShiftPrefix* o) { return is_finite3(o->throughput) && isfinite(o->ratio); }
