// Conjugate-gradient vector updates. Step lengths come from the scalar buffer `scal` (one float4
// per slot, a lane per colour channel) written by recon_sum_final, so the three channels run
// their own CG in lockstep without the host reading anything but the residual. Layout: grid.h.
#include "recon/grid.h"

// x += a p, r -= a q with a = scal[num] / scal[den].
__kernel void cg_update_xr(__global float* x, __global float* r, __global const float* p,
                           __global const float* q, __global const float4* scal, int num,
                           int den, int ws, int h) {
  RECON_CHUNK(o, c, ws, h)
  float a = recon_ratio(scal, num, den, c);
  VSTORE(VLOAD(x + o) + a * VLOAD(p + o), x + o);
  VSTORE(VLOAD(r + o) - a * VLOAD(q + o), r + o);
}

// The same, also the partial sums of r * r (reducing launch).
__kernel void cg_update_xr_dot(__global float* x, __global float* r, __global const float* p,
                               __global const float* q, __global const float4* scal, int num,
                               int den, int ws, int h, __global float* partial) {
  __local float scratch[RECON_LOCAL];
  floatv s = (floatv)(0.0f);
  RECON_FOR_SHARE(o, c, ws, h) {
    float a = recon_ratio(scal, num, den, c);
    VSTORE(VLOAD(x + o) + a * VLOAD(p + o), x + o);
    floatv ri = VLOAD(r + o) - a * VLOAD(q + o);
    VSTORE(ri, r + o);
    s += ri * ri;
  }
  RECON_WRITE_PARTIAL(s, scratch, partial)
}

// p = z + b p with b = scal[num] / scal[den] (0 when scal[den] is 0: a fresh start).
__kernel void cg_update_p(__global float* p, __global const float* z,
                          __global const float4* scal, int num, int den, int ws, int h) {
  RECON_CHUNK(o, c, ws, h)
  float b = recon_ratio(scal, num, den, c);
  VSTORE(VLOAD(z + o) + b * VLOAD(p + o), p + o);
}
