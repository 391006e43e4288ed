// Per-pixel accumulators of the gradient-domain groups (GPT_ACC_*), indexed by pixel over the
// whole image so the gather can read neighbours.
#pragma once
#include "shared/gpt_types.h"

inline void acc_add(__global float4* acc, uint pixel, int slot, float3 c) {
  if (c.x != 0.0f || c.y != 0.0f || c.z != 0.0f) acc[pixel * GPT_ACC_COUNT + slot] += (float4)(c, 0.0f);
}

// Emission seen from the camera: GPT_ACC_SEEN's w counts the samples that saw some
// (gradient/seen_coverage.h).
inline void acc_add_seen(__global float4* acc, uint pixel, float3 c) {
  if (c.x != 0.0f || c.y != 0.0f || c.z != 0.0f) acc[pixel * GPT_ACC_COUNT + GPT_ACC_SEEN] += (float4)(c, 1.0f);
}
