// Embree's answer for a shadow ray: it sets tfar to -inf on a blocked one and leaves the others.
#pragma once
#include "shared/ray_types.h"

inline int shadow_unoccluded(float tfar) { return tfar >= 0.0f; }

// Adds the contributions of the shadow rays Embree found unoccluded to the film pixels their ids
// name (one ray per pixel and step: no two work items add to one pixel).
__kernel void path_shadow_add(uint count, __global const GdrRay* shadow_rays, __global const float4* shadow_values,
                              __global float4* film) {
  uint k = get_global_id(0);
  if (k >= count) return;
  if (shadow_unoccluded(shadow_rays[k].tfar)) film[shadow_rays[k].id] += shadow_values[k];
}
