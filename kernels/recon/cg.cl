// Conjugate-gradient vector updates. Step lengths come from the scalar buffer `scal` (one float4
// per slot, a value per colour channel) written by recon_sum_final, so the three channels run
// their own CG in lockstep without the host reading anything but the residual.
#include "recon/grid.h"

// x += a p, r -= a q with a = scal[num] / scal[den].
__kernel void cg_update_xr(__global float4* x, __global float4* r, __global const float4* p,
                           __global const float4* q, __global const float4* scal, int num,
                           int den, int n) {
  int i = get_global_id(0);
  if (i >= n) return;
  float4 a = recon_ratio(scal[num], scal[den]);
  x[i] += a * p[i];
  r[i] -= a * q[i];
}

// The same, also summing r * r per group into partial (global size = groups * RECON_LOCAL).
__kernel void cg_update_xr_dot(__global float4* x, __global float4* r, __global const float4* p,
                               __global const float4* q, __global const float4* scal, int num,
                               int den, int n, __global float4* partial) {
  __local float4 scratch[RECON_LOCAL];
  float4 a = recon_ratio(scal[num], scal[den]);
  float4 s = (float4)(0.0f);
  RECON_FOR_SHARE(i, n) {
    x[i] += a * p[i];
    float4 ri = r[i] - a * q[i];
    r[i] = ri;
    s += ri * ri;
  }
  float4 total = recon_group_sum(s, scratch);
  if (get_local_id(0) == 0) partial[get_group_id(0)] = total;
}

// p = z + b p with b = scal[num] / scal[den] (0 when scal[den] is 0: a fresh start).
__kernel void cg_update_p(__global float4* p, __global const float4* z,
                          __global const float4* scal, int num, int den, int n) {
  int i = get_global_id(0);
  if (i >= n) return;
  float4 b = recon_ratio(scal[num], scal[den]);
  p[i] = z[i] + b * p[i];
}
