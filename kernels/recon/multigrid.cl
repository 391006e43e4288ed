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

// bc = P^T (b - A x): each coarse pixel sums the fine residual of its children.
__kernel void mg_restrict_residual(__global const float4* x, __global const float4* b,
                                   __global const float4* wp, __global const float4* wx,
                                   __global const float4* wy, int wf, int hf,
                                   __global float4* bc, int wc, int hc) {
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
      s += b[fy * wf + fx] - recon_apply_at(x, wp, wx, wy, fx, fy, wf, hf);
    }
  }
  bc[i] = s;
}

// xf += P xc: every fine pixel adds its aggregate's correction.
__kernel void mg_prolong_add(__global const float4* xc, int wc, __global float4* xf, int wf,
                             int hf) {
  int i = get_global_id(0);
  if (i >= wf * hf) return;
  int fx = i % wf, fy = i / wf;
  xf[i] += xc[(fy / 2) * wc + fx / 2];
}
