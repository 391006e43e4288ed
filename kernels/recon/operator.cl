// The screened Poisson operator A = Wp + Dx^T Wx Dx + Dy^T Wy Dy, matrix-free. Layout: grid.h.
#include "recon/grid.h"

// y = A x.
__kernel void recon_apply(__global const float* x, __global const float* wp,
                          __global const float* wx, __global const float* wy, int ws, int h,
                          __global float* y) {
  RECON_CHUNK(o, c, ws, h)
  VSTORE(recon_apply_at(x, wp, wx, wy, o, ws), y + o);
}

// r = b - A x.
__kernel void recon_residual(__global const float* x, __global const float* b,
                             __global const float* wp, __global const float* wx,
                             __global const float* wy, int ws, int h, __global float* r) {
  RECON_CHUNK(o, c, ws, h)
  VSTORE(VLOAD(b + o) - recon_apply_at(x, wp, wx, wy, o, ws), r + o);
}
