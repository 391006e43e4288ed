// The screened Poisson operator A = Wp + Dx^T Wx Dx + Dy^T Wy Dy, matrix-free.
#include "recon/grid.h"

// y = A x, one item per pixel.
__kernel void recon_apply(__global const float4* x, __global const float4* wp,
                          __global const float4* wx, __global const float4* wy, int w, int h,
                          __global float4* y) {
  int i = get_global_id(0);
  if (i >= w * h) return;
  y[i] = recon_apply_at(x, wp, wx, wy, i % w, i / w, w, h);
}

// r = b - A x, one item per pixel.
__kernel void recon_residual(__global const float4* x, __global const float4* b,
                             __global const float4* wp, __global const float4* wx,
                             __global const float4* wy, int w, int h, __global float4* r) {
  int i = get_global_id(0);
  if (i >= w * h) return;
  r[i] = b[i] - recon_apply_at(x, wp, wx, wy, i % w, i / w, w, h);
}

// q = A p and partial[group] = sum of p * q over the group's pixels (one pass instead of two).
// Global size = groups * RECON_LOCAL.
__kernel void recon_apply_dot(__global const float4* p, __global const float4* wp,
                              __global const float4* wx, __global const float4* wy, int w, int h,
                              __global float4* q, __global float4* partial) {
  __local float4 scratch[RECON_LOCAL];
  float4 s = (float4)(0.0f);
  int n = w * h;
  RECON_FOR_SHARE(i, n) {
    float4 v = recon_apply_at(p, wp, wx, wy, i % w, i / w, w, h);
    q[i] = v;
    s += p[i] * v;
  }
  float4 total = recon_group_sum(s, scratch);
  if (get_local_id(0) == 0) partial[get_group_id(0)] = total;
}
