// Delta-lobe copy: at a vertex where the base took a delta lobe, the offset takes the same lobe.
#pragma once
#include "bsdf/bsdf.h"

// The offset's sample of the delta lobe the base took (reflection or transmission), without
// random choice: the lobe is selected by u.x, so both ends of its range are tried. Returns 0
// when the offset's BSDF has no such lobe here (e.g. total internal reflection).
inline int bsdf_sample_delta_lobe(const Bsdf* b, float3 wo, int transmitted, BsdfSample* s) {
  const float ends[2] = {0.0f, 0x1.fffffep-1f};
  for (int i = 0; i < 2; ++i) {
    if (bsdf_sample(b, wo, (float3)(ends[i], 0.5f, 0.5f), s) && s->delta && s->transmitted == transmitted) {
      return 1;
    }
  }
  return 0;
}
