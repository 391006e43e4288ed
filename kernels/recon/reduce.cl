// Dot products in two launches: each work-group sums its share of one channel into
// partial[channel][group], then one group per channel adds the partials into that channel's lane
// of a slot of the scalar buffer that the CG kernels read directly (no host round trip for step
// lengths). Layout: grid.h.
#include "recon/grid.h"

// Reducing launch: partial sums of a * b.
__kernel void recon_dot_partial(__global const float* a, __global const float* b, int ws, int h,
                                __global float* partial) {
  __local float scratch[RECON_LOCAL];
  floatv s = (floatv)(0.0f);
  RECON_FOR_SHARE(o, c, ws, h) s += VLOAD(a + o) * VLOAD(b + o);
  RECON_WRITE_PARTIAL(s, scratch, partial)
}

// Launched (RECON_LOCAL, 3): lane c of the float4 slot `slot` = sum of partial[c][0 .. groups).
__kernel void recon_sum_final(__global const float* partial, int groups, __global float* scal,
                              int slot) {
  __local float scratch[RECON_LOCAL];
  int c = get_global_id(1);
  float s = 0.0f;
  for (int i = get_local_id(0); i < groups; i += RECON_LOCAL) s += partial[c * groups + i];
  float total = recon_group_sum(s, scratch);
  if (get_local_id(0) == 0) scal[4 * slot + c] = total;
}
