// Multigrid V-cycle used as the preconditioner of the fast solver. Coarse levels aggregate 2x2
// pixels; with piecewise-constant prolongation P the Galerkin operator P^T A P is again a
// screened Poisson operator whose weights are sums of fine weights (edges inside an aggregate
// cancel), so jumping IRLS weights are coarsened consistently. Damped Jacobi smooths.
#include "recon/grid.h"

// Coarse weights of P^T A P: wp sums the 2x2 children; an edge sums the fine edges it crosses.
__kernel void mg_coarsen(__global const float4* wpf, __global const float4* wxf,
                         __global const float4* wyf, int wf, int hf, __global float4* wpc,
                         __global float4* wxc, __global float4* wyc, int wc, int hc) {
  int i = get_global_id(0);
  if (i >= wc * hc) return;
  int cx = i % wc, cy = i / wc;
  float4 sp = (float4)(0.0f), sx = (float4)(0.0f), sy = (float4)(0.0f);
  for (int dy = 0; dy < 2; ++dy) {
    int fy = 2 * cy + dy;
    if (fy >= hf) break;
    for (int dx = 0; dx < 2; ++dx) {
      int fx = 2 * cx + dx;
      if (fx >= wf) break;
      int f = fy * wf + fx;
      sp += wpf[f];
      if (dx == 1) sx += wxf[f];
      if (dy == 1) sy += wyf[f];
    }
  }
  // The edge right of the last coarse column (or below the last row) leaves the image.
  wpc[i] = sp;
  wxc[i] = cx + 1 < wc ? sx : (float4)(0.0f);
  wyc[i] = cy + 1 < hc ? sy : (float4)(0.0f);
}

// x = omega D^-1 b: one Jacobi sweep from a zero guess.
__kernel void mg_jacobi_zero(__global const float4* b, __global const float4* dinv, float omega,
                             int n, __global float4* x) {
  int i = get_global_id(0);
  if (i >= n) return;
  x[i] = omega * dinv[i] * b[i];
}

// xout = x + omega D^-1 (b - A x).
__kernel void mg_jacobi(__global const float4* x, __global const float4* b,
                        __global const float4* wp, __global const float4* wx,
                        __global const float4* wy, __global const float4* dinv, float omega,
                        int w, int h, __global float4* xout) {
  int i = get_global_id(0);
  if (i >= w * h) return;
  float4 r = b[i] - recon_apply_at(x, wp, wx, wy, i % w, i / w, w, h);
  xout[i] = x[i] + omega * dinv[i] * r;
}

// The pre-smoothed estimate from a zero guess, x0 = omega D^-1 b, recomputed where needed
// rather than stored.
inline float4 mg_x0(__global const float4* b, __global const float4* dinv, float omega, int j) {
  return omega * dinv[j] * b[j];
}

// bc = P^T (b - A x0): pre-smoothing, residual and restriction in one pass.
__kernel void mg_restrict_presmoothed(__global const float4* b, __global const float4* dinv,
                                      float omega, __global const float4* wp,
                                      __global const float4* wx, __global const float4* wy,
                                      int wf, int hf, __global float4* bc, int wc, int hc) {
  int i = get_global_id(0);
  if (i >= wc * hc) return;
  int cx = i % wc, cy = i / wc;
  float4 s = (float4)(0.0f);
  for (int dy = 0; dy < 2; ++dy) {
    int fy = 2 * cy + dy;
    if (fy >= hf) break;
    for (int dx = 0; dx < 2; ++dx) {
      int fx = 2 * cx + dx;
      if (fx >= wf) break;
      int f = fy * wf + fx;
      float4 xf = mg_x0(b, dinv, omega, f);
      float4 ax = wp[f] * xf;
      if (fx + 1 < wf) ax += wx[f] * (xf - mg_x0(b, dinv, omega, f + 1));
      if (fx > 0) ax += wx[f - 1] * (xf - mg_x0(b, dinv, omega, f - 1));
      if (fy + 1 < hf) ax += wy[f] * (xf - mg_x0(b, dinv, omega, f + wf));
      if (fy > 0) ax += wy[f - wf] * (xf - mg_x0(b, dinv, omega, f - wf));
      s += b[f] - ax;
    }
  }
  bc[i] = s;
}

// y = x0 + P xc (the coarse correction added to the pre-smoothed estimate), at fine pixel j.
inline float4 mg_corrected(__global const float4* b, __global const float4* dinv, float omega,
                           __global const float4* xc, int wc, int fx, int fy, int wf) {
  return mg_x0(b, dinv, omega, fy * wf + fx) + xc[(fy / 2) * wc + fx / 2];
}

// y = x0 + P xc: the coarse correction added to the pre-smoothed estimate, followed by an
// mg_jacobi sweep. (Fusing the two, recomputing y at the neighbours, measured slower on PoCL.)
__kernel void mg_correct(__global const float4* b, __global const float4* dinv, float omega,
                         __global const float4* xc, int wc, int wf, int hf, __global float4* y) {
  int i = get_global_id(0);
  if (i >= wf * hf) return;
  y[i] = mg_corrected(b, dinv, omega, xc, wc, i % wf, i / wf, wf);
}
