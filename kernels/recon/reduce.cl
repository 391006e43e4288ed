// Dot products in two launches: each work-group sums its share into partial[group], then one
// group adds the partials into a slot of the scalar buffer that the CG kernels read directly
// (no host round trip for step lengths).
#include "recon/grid.h"

// Global size = groups * RECON_LOCAL; items stride over the n pixels.
__kernel void recon_dot_partial(__global const float4* a, __global const float4* b, int n,
                                __global float4* partial) {
  __local float4 scratch[RECON_LOCAL];
  float4 s = (float4)(0.0f);
  RECON_FOR_SHARE(i, n) s += a[i] * b[i];
  float4 total = recon_group_sum(s, scratch);
  if (get_local_id(0) == 0) partial[get_group_id(0)] = total;
}

// One group: scal[slot] = sum of partial[0 .. groups).
__kernel void recon_sum_final(__global const float4* partial, int groups, __global float4* scal,
                              int slot) {
  __local float4 scratch[RECON_LOCAL];
  float4 s = (float4)(0.0f);
  for (int i = get_local_id(0); i < groups; i += RECON_LOCAL) s += partial[i];
  float4 total = recon_group_sum(s, scratch);
  if (get_local_id(0) == 0) scal[slot] = total;
}
