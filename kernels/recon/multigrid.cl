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
// Edges leaving the image come out zero because the fine ones there are. Also the coarse
// Jacobi step, with the left and upper coarse edges summed again here. Launched like
// mg_restrict_presmoothed.
__kernel void mg_coarsen(__global const float* wpf, __global const float* wxf,
                         __global const float* wyf, int wsf, int hf, __global float* wpc,
                         __global float* wxc, __global float* wyc, __global float* stepc,
                         int wsc, int hc) {
  const int c = get_global_id(1);
  const int per_row = wsf / MG_ITEM_COLS;
  const int k = get_global_id(0);
  if (k >= per_row * hc) return;
  const int cy = k / per_row, j = k % per_row;
  // Fine rows 2 cy and 2 cy + 1 (the latter may be the gap row below the plane: all zero); row
  // 2 cy - 1 holds the edges to the coarse row above (the gap row above the plane for cy = 0).
  const int f = gdr_recon_plane(c, wsf, hf) + 2 * cy * wsf + j * MG_ITEM_COLS;
  const int e = gdr_recon_plane(c, wsc, hc) + cy * wsc + j * (MG_ITEM_COLS / 2);
#if RECON_VEC == 16
  float16 p = VLOAD(wpf + f) + VLOAD(wpf + f + wsf);
  float16 x = VLOAD(wxf + f) + VLOAD(wxf + f + wsf);
  float16 xl = VLOAD(wxf + f - 2) + VLOAD(wxf + f + wsf - 2);
  float16 y = VLOAD(wyf + f + wsf), yu = VLOAD(wyf + f - wsf);
  float8 pc = p.even + p.odd, xc = x.odd, yc = y.even + y.odd;
  float8 d = pc + xc + yc + xl.odd + yu.even + yu.odd;
  VSTORE8(pc, wpc + e);
  VSTORE8(xc, wxc + e);
  VSTORE8(yc, wyc + e);
  VSTORE8(select((float8)(0.0f), RECON_OMEGA / d, d > 0.0f), stepc + e);
#else
  float pc = wpf[f] + wpf[f + 1] + wpf[f + wsf] + wpf[f + wsf + 1];
  float xc = wxf[f + 1] + wxf[f + wsf + 1];
  float yc = wyf[f + wsf] + wyf[f + wsf + 1];
  float d = pc + xc + yc + wxf[f - 1] + wxf[f + wsf - 1] + wyf[f - wsf] + wyf[f - wsf + 1];
  wpc[e] = pc;
  wxc[e] = xc;
  wyc[e] = yc;
  stepc[e] = d > 0.0f ? RECON_OMEGA / d : 0.0f;
#endif
}

// x = omega D^-1 b (`step` holds omega D^-1): one Jacobi sweep from a zero guess.
__kernel void mg_jacobi_zero(__global const float* b, __global const float* step,
                             int ws, int h, __global float* x) {
  RECON_CHUNK(o, c, ws, h)
  VSTORE(VLOAD(step + o) * VLOAD(b + o), x + o);
}

// xout = x + omega D^-1 (b - A x).
__kernel void mg_jacobi(__global const float* x, __global const float* b,
                        __global const float* wp, __global const float* wx,
                        __global const float* wy, __global const float* step,
                        int ws, int h, __global float* xout) {
  RECON_CHUNK(o, c, ws, h)
  floatv r = VLOAD(b + o) - recon_apply_at(x, wp, wx, wy, o, ws);
  VSTORE(VLOAD(x + o) + VLOAD(step + o) * r, xout + o);
}

// The pre-smoothed estimate from a zero guess, x0 = omega D^-1 b, recomputed where needed
// rather than stored.
RECON_INLINE floatv mg_x0(__global const float* b, __global const float* step, int o) {
  return VLOAD(step + o) * VLOAD(b + o);
}

// b - A x0 at the chunk starting at o.
RECON_INLINE floatv mg_presmoothed_residual(__global const float* b, __global const float* step,
                                      __global const float* wp,
                                      __global const float* wx, __global const float* wy, int o,
                                      int ws) {
  return VLOAD(b + o) - recon_stencil_at(wp, wx, wy, o, ws, mg_x0(b, step, o),
                                         mg_x0(b, step, o + 1), mg_x0(b, step, o - 1),
                                         mg_x0(b, step, o + ws), mg_x0(b, step, o - ws));
}

// bc = P^T (b - A x0): pre-smoothing, residual and restriction in one pass. 2D launch over
// (item of a coarse row * hc, channel), wsf / MG_ITEM_COLS items per coarse row.
__kernel void mg_restrict_presmoothed(__global const float* b, __global const float* step,
                                      __global const float* wp,
                                      __global const float* wx, __global const float* wy,
                                      int wsf, int hf, __global float* bc, int wsc, int hc) {
  const int c = get_global_id(1);
  const int per_row = wsf / MG_ITEM_COLS;
  const int k = get_global_id(0);
  if (k >= per_row * hc) return;
  const int cy = k / per_row, j = k % per_row;
  // Fine rows 2 cy and 2 cy + 1 (the latter may be the gap row, whose residual is 0).
  const int f = gdr_recon_plane(c, wsf, hf) + 2 * cy * wsf + j * MG_ITEM_COLS;
  const int e = gdr_recon_plane(c, wsc, hc) + cy * wsc + j * (MG_ITEM_COLS / 2);
#if RECON_VEC == 16
  // mg_presmoothed_residual on both rows, sharing x0 between them.
  const int g = f + wsf;
  float16 x0f = mg_x0(b, step, f), x0g = mg_x0(b, step, g);
  float16 af = recon_stencil_at(wp, wx, wy, f, wsf, x0f, mg_x0(b, step, f + 1),
                                mg_x0(b, step, f - 1), x0g, mg_x0(b, step, f - wsf));
  float16 ag = recon_stencil_at(wp, wx, wy, g, wsf, x0g, mg_x0(b, step, g + 1),
                                mg_x0(b, step, g - 1), mg_x0(b, step, g + wsf), x0f);
  float16 s = VLOAD(b + f) - af + VLOAD(b + g) - ag;
  VSTORE8(s.even + s.odd, bc + e);
#else
  bc[e] = mg_presmoothed_residual(b, step, wp, wx, wy, f, wsf) +
          mg_presmoothed_residual(b, step, wp, wx, wy, f + 1, wsf) +
          mg_presmoothed_residual(b, step, wp, wx, wy, f + wsf, wsf) +
          mg_presmoothed_residual(b, step, wp, wx, wy, f + wsf + 1, wsf);
#endif
}

// z = y + omega D^-1 (b - A y) for y = x0 + P xc: the coarse correction added to the pre-smoothed
// estimate, then one Jacobi sweep, with y recomputed at the neighbours instead of stored. `rel`
// is the chunk's offset in its plane (row fy, column fx).
RECON_INLINE floatv mg_correct_smooth_at(__global const float* b, __global const float* step,
                                   __global const float* wp,
                                   __global const float* wx, __global const float* wy,
                                   __global const float* xc, int wsc, int hc, int c, int rel,
                                   int o, int ws) {
  const int fy = rel / ws, fx = rel % ws;
  // Coarse rows of fine rows fy - 1, fy, fy + 1 (floor division; row -1 is the gap row above).
  const int row0 = gdr_recon_plane(c, wsc, hc) + (fx >> 1);
  const int e = row0 + (fy >> 1) * wsc;
  const int e_up = row0 + (((fy + 1) >> 1) - 1) * wsc;
  const int e_down = row0 + ((fy + 1) >> 1) * wsc;
#if RECON_VEC == 16
  // Fine columns fx + k (k < 16) have coarse column fx / 2 + k / 2; shifted by one either way,
  // (k + 1) / 2 from one coarse column further left or from the same one.
  const uint16 same = (uint16)(0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7);
  const uint16 shifted = (uint16)(0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8);
  floatv up_c = shuffle(VLOAD8(xc + e), same);
  floatv up_l = shuffle(VLOAD(xc + e - 1), shifted);
  floatv up_r = shuffle(VLOAD(xc + e), shifted);
  floatv up_u = shuffle(VLOAD8(xc + e_up), same);
  floatv up_d = shuffle(VLOAD8(xc + e_down), same);
#else
  // Column fx - 1 = -1 reads the coarse row's element before it (finite, weight zero).
  floatv up_c = xc[e], up_u = xc[e_up], up_d = xc[e_down];
  floatv up_l = xc[e + ((fx + 1) >> 1) - 1 - (fx >> 1)], up_r = xc[e + ((fx + 1) >> 1) - (fx >> 1)];
#endif
  floatv y = mg_x0(b, step, o) + up_c;
  floatv ay = recon_stencil_at(wp, wx, wy, o, ws, y, mg_x0(b, step, o + 1) + up_r,
                               mg_x0(b, step, o - 1) + up_l, mg_x0(b, step, o + ws) + up_d,
                               mg_x0(b, step, o - ws) + up_u);
  return y + VLOAD(step + o) * (VLOAD(b + o) - ay);
}

// The post-smoothed correction of one level (see mg_correct_smooth_at).
__kernel void mg_correct_smooth(__global const float* b, __global const float* step,
                                __global const float* wp, __global const float* wx,
                                __global const float* wy, __global const float* xc, int wsc,
                                int hc, int ws, int h, __global float* z) {
  RECON_CHUNK(o, c, ws, h)
  VSTORE(mg_correct_smooth_at(b, step, wp, wx, wy, xc, wsc, hc, c,
                              o - gdr_recon_plane(c, ws, h), o, ws),
         z + o);
}

// The same on the finest level, with the partial sums of b * z (r * z for the PCG; reducing
// launch).
__kernel void mg_correct_smooth_dot(__global const float* b, __global const float* step,
                                    __global const float* wp,
                                    __global const float* wx, __global const float* wy,
                                    __global const float* xc, int wsc, int hc, int ws, int h,
                                    __global float* z, __global float* partial) {
  __local float scratch[RECON_LOCAL];
  floatv s = (floatv)(0.0f);
  RECON_FOR_SHARE(o, c, ws, h) {
    floatv zi = mg_correct_smooth_at(b, step, wp, wx, wy, xc, wsc, hc, c,
                                     o - gdr_recon_plane(c, ws, h), o, ws);
    VSTORE(zi, z + o);
    s += VLOAD(b + o) * zi;
  }
  RECON_WRITE_PARTIAL(s, scratch, partial)
}
