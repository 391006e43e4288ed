// Random-number replay: the offset samples its own BSDF with the base's random numbers.
#pragma once
#include "bsdf/bsdf.h"

// The offset's sample at local wo from the base's numbers u; 0 where there is none, or where it
// takes a delta lobe when the base did not (or the reverse). The path-space Jacobian is
// p(x)/p(y), so f(y)|J|/p(x) is the sample's own weight and the pdf ratio does not change.
inline int shift_replay(const Bsdf* b, float3 wo, float4 u, int base_delta, BsdfSample* s) {
  return bsdf_sample(b, wo, u.xyz, s) && s->delta == base_delta;
}
