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

// p = z + b p_old (b = scal[num] / scal[den]), q = A p and the partial sums of p * q in one pass
// (reducing launch). p at the neighbours is recomputed from z and p_old, so p and p_old must be
// different buffers.
__kernel void cg_update_p_apply_dot(__global const float* p_old, __global const float* z,
                                    __global const float4* scal, int num, int den,
                                    __global const float* wp, __global const float* wx,
                                    __global const float* wy, int ws, int h, __global float* p,
                                    __global float* q, __global float* partial) {
  __local float scratch[RECON_LOCAL];
  floatv s = (floatv)(0.0f);
  RECON_FOR_SHARE(o, c, ws, h) {
    float b = recon_ratio(scal, num, den, c);
#define CG_P_AT(k) (VLOAD(z + (k)) + b * VLOAD(p_old + (k)))
    floatv pi = CG_P_AT(o);
    floatv qi = recon_stencil_at(wp, wx, wy, o, ws, pi, CG_P_AT(o + 1), CG_P_AT(o - 1),
                                 CG_P_AT(o + ws), CG_P_AT(o - ws));
#undef CG_P_AT
    VSTORE(pi, p + o);
    VSTORE(qi, q + o);
    s += pi * qi;
  }
  RECON_WRITE_PARTIAL(s, scratch, partial)
}
