// Multigrid V-cycle used as the preconditioner of the fast solver. Coarse levels aggregate 2x2
// pixels; with piecewise-constant prolongation P the Galerkin operator P^T A P is again a
// screened Poisson operator whose weights are sums of fine weights (edges inside an aggregate
// cancel), so jumping IRLS weights are coarsened consistently. Damped Jacobi smooths. Every level
// has the layout of grid.h with its own width, height and row stride.
#include "recon/grid.h"

// Fine columns one restriction item covers (two rows of them): 16 on CPUs (8 coarse pixels),
// 2 otherwise (one coarse pixel).
#define MG_ITEM_COLS (RECON_VEC == 1 ? 2 : RECON_VEC)

// Coarse weights of P^T A P: wp sums the 2x2 children; an edge sums the fine edges it crosses.
// Edges leaving the image come out zero because the fine ones there are. Launched like
// mg_restrict_presmoothed.
__kernel void mg_coarsen(__global const float* wpf, __global const float* wxf,
                         __global const float* wyf, int wsf, int hf, __global float* wpc,
                         __global float* wxc, __global float* wyc, int wsc, int hc) {
  const int c = get_global_id(1);
  const int per_row = wsf / MG_ITEM_COLS;
  const int k = get_global_id(0);
  if (k >= per_row * hc) return;
  const int cy = k / per_row, j = k % per_row;
  // Fine rows 2 cy and 2 cy + 1 (the latter may be the gap row below the plane: all zero).
  const int f = recon_plane(c, wsf, hf) + 2 * cy * wsf + j * MG_ITEM_COLS;
  const int e = recon_plane(c, wsc, hc) + cy * wsc + j * (MG_ITEM_COLS / 2);
#if RECON_VEC == 16
  float16 p = vload16(0, wpf + f) + vload16(0, wpf + f + wsf);
  float16 x = vload16(0, wxf + f) + vload16(0, wxf + f + wsf);
  float16 y = vload16(0, wyf + f + wsf);
  vstore8(p.even + p.odd, 0, wpc + e);
  vstore8(x.odd, 0, wxc + e);
  vstore8(y.even + y.odd, 0, wyc + e);
#else
  wpc[e] = wpf[f] + wpf[f + 1] + wpf[f + wsf] + wpf[f + wsf + 1];
  wxc[e] = wxf[f + 1] + wxf[f + wsf + 1];
  wyc[e] = wyf[f + wsf] + wyf[f + wsf + 1];
#endif
}

// x = omega D^-1 b: one Jacobi sweep from a zero guess.
__kernel void mg_jacobi_zero(__global const float* b, __global const float* dinv, float omega,
                             int ws, int h, __global float* x) {
  RECON_CHUNK(o, c, ws, h)
  VSTORE(omega * VLOAD(dinv + o) * VLOAD(b + o), x + o);
}

// xout = x + omega D^-1 (b - A x).
__kernel void mg_jacobi(__global const float* x, __global const float* b,
                        __global const float* wp, __global const float* wx,
                        __global const float* wy, __global const float* dinv, float omega,
                        int ws, int h, __global float* xout) {
  RECON_CHUNK(o, c, ws, h)
  floatv r = VLOAD(b + o) - recon_apply_at(x, wp, wx, wy, o, ws);
  VSTORE(VLOAD(x + o) + omega * VLOAD(dinv + o) * r, xout + o);
}

// The pre-smoothed estimate from a zero guess, x0 = omega D^-1 b, recomputed where needed
// rather than stored.
inline floatv mg_x0(__global const float* b, __global const float* dinv, float omega, int o) {
  return omega * VLOAD(dinv + o) * VLOAD(b + o);
}

// b - A x0 at the chunk starting at o.
inline floatv mg_presmoothed_residual(__global const float* b, __global const float* dinv,
                                      float omega, __global const float* wp,
                                      __global const float* wx, __global const float* wy, int o,
                                      int ws) {
  floatv x0 = mg_x0(b, dinv, omega, o);
  floatv ax = VLOAD(wp + o) * x0 + VLOAD(wx + o) * (x0 - mg_x0(b, dinv, omega, o + 1)) +
              VLOAD(wx + o - 1) * (x0 - mg_x0(b, dinv, omega, o - 1)) +
              VLOAD(wy + o) * (x0 - mg_x0(b, dinv, omega, o + ws)) +
              VLOAD(wy + o - ws) * (x0 - mg_x0(b, dinv, omega, o - ws));
  return VLOAD(b + o) - ax;
}

// bc = P^T (b - A x0): pre-smoothing, residual and restriction in one pass. 2D launch over
// (item of a coarse row * hc, channel), wsf / MG_ITEM_COLS items per coarse row.
__kernel void mg_restrict_presmoothed(__global const float* b, __global const float* dinv,
                                      float omega, __global const float* wp,
                                      __global const float* wx, __global const float* wy,
                                      int wsf, int hf, __global float* bc, int wsc, int hc) {
  const int c = get_global_id(1);
  const int per_row = wsf / MG_ITEM_COLS;
  const int k = get_global_id(0);
  if (k >= per_row * hc) return;
  const int cy = k / per_row, j = k % per_row;
  // Fine rows 2 cy and 2 cy + 1 (the latter may be the gap row, whose residual is 0).
  const int f = recon_plane(c, wsf, hf) + 2 * cy * wsf + j * MG_ITEM_COLS;
  const int e = recon_plane(c, wsc, hc) + cy * wsc + j * (MG_ITEM_COLS / 2);
#if RECON_VEC == 16
  float16 s = mg_presmoothed_residual(b, dinv, omega, wp, wx, wy, f, wsf) +
              mg_presmoothed_residual(b, dinv, omega, wp, wx, wy, f + wsf, wsf);
  vstore8(s.even + s.odd, 0, bc + e);
#else
  bc[e] = mg_presmoothed_residual(b, dinv, omega, wp, wx, wy, f, wsf) +
          mg_presmoothed_residual(b, dinv, omega, wp, wx, wy, f + 1, wsf) +
          mg_presmoothed_residual(b, dinv, omega, wp, wx, wy, f + wsf, wsf) +
          mg_presmoothed_residual(b, dinv, omega, wp, wx, wy, f + wsf + 1, wsf);
#endif
}

// y = x0 + P xc: the coarse correction added to the pre-smoothed estimate; an mg_jacobi sweep
// follows. (Fusing the two, recomputing y at the neighbours, measured slower on PoCL.)
__kernel void mg_correct(__global const float* b, __global const float* dinv, float omega,
                         __global const float* xc, int wsc, int hc, int wsf, int hf,
                         __global float* y) {
  RECON_CHUNK(o, c, wsf, hf)
  const int per_row = wsf / RECON_VEC;
  const int fy = get_global_id(0) / per_row, j = get_global_id(0) % per_row;
  const int e = recon_plane(c, wsc, hc) + (fy / 2) * wsc + (j * RECON_VEC) / 2;
#if RECON_VEC == 16
  float16 up = shuffle(vload8(0, xc + e), (uint16)(0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7));
#else
  float up = xc[e];
#endif
  VSTORE(mg_x0(b, dinv, omega, o) + up, y + o);
}
