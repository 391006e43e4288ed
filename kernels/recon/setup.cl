// Problem set-up for the screened Poisson reconstruction: packing and checking the inputs,
// the per-term weights (L2, or IRLS for L1), the right-hand side, the Jacobi diagonal, the
// objective value, and unpacking the result.
#include "recon/grid.h"

inline float recon_take(float v, float* mask, __global uint* nonfinite) {
  if (isfinite(v)) return v;
  *mask = 0.0f;
  atomic_inc(nonfinite);
  return 0.0f;
}

// Interleaved RGB primal / dx / dy -> float4 planes; a non-finite value is counted and its term
// dropped (mask 0). The last column of dx and the last row of dy are no terms at all.
__kernel void recon_pack(__global const float* primal, __global const float* dx,
                         __global const float* dy, int w, int h, __global float4* P,
                         __global float4* Gx, __global float4* Gy, __global float4* mp,
                         __global float4* mx, __global float4* my, __global uint* nonfinite) {
  int i = get_global_id(0);
  if (i >= w * h) return;
  int px = i % w, py = i / w;
  float p[3], gx[3], gy[3], cp[3], cx[3], cy[3];
  for (int c = 0; c < 3; ++c) {
    cp[c] = 1.0f;
    cx[c] = px + 1 < w ? 1.0f : 0.0f;
    cy[c] = py + 1 < h ? 1.0f : 0.0f;
    p[c] = recon_take(primal[3 * i + c], &cp[c], nonfinite);
    gx[c] = cx[c] > 0.0f ? recon_take(dx[3 * i + c], &cx[c], nonfinite) : 0.0f;
    gy[c] = cy[c] > 0.0f ? recon_take(dy[3 * i + c], &cy[c], nonfinite) : 0.0f;
  }
  P[i] = (float4)(p[0], p[1], p[2], 0.0f);
  Gx[i] = (float4)(gx[0], gx[1], gx[2], 0.0f);
  Gy[i] = (float4)(gy[0], gy[1], gy[2], 0.0f);
  mp[i] = (float4)(cp[0], cp[1], cp[2], 0.0f);
  mx[i] = (float4)(cx[0], cx[1], cx[2], 0.0f);
  my[i] = (float4)(cy[0], cy[1], cy[2], 0.0f);
}

// L2: every present term has weight 1 (alpha^2 for the primal term).
__kernel void recon_weights_l2(__global const float4* mp, __global const float4* mx,
                               __global const float4* my, float alpha2, int n,
                               __global float4* wp, __global float4* wx, __global float4* wy) {
  int i = get_global_id(0);
  if (i >= n) return;
  wp[i] = alpha2 * mp[i];
  wx[i] = mx[i];
  wy[i] = my[i];
}

// L1 by iteratively reweighted least squares: a term with residual e gets weight 1/(|e| + reg),
// so that w e^2 ~ |e| at the current estimate x.
__kernel void recon_weights_l1(__global const float4* x, __global const float4* P,
                               __global const float4* Gx, __global const float4* Gy,
                               __global const float4* mp, __global const float4* mx,
                               __global const float4* my, float alpha, float reg, int w, int h,
                               __global float4* wp, __global float4* wx, __global float4* wy) {
  int i = get_global_id(0);
  if (i >= w * h) return;
  int px = i % w, py = i / w;
  float4 xi = x[i];
  float4 ep = alpha * (xi - P[i]);
  wp[i] = alpha * alpha * mp[i] / (fabs(ep) + reg);
  float4 ex = px + 1 < w ? x[i + 1] - xi - Gx[i] : (float4)(0.0f);
  float4 ey = py + 1 < h ? x[i + w] - xi - Gy[i] : (float4)(0.0f);
  wx[i] = mx[i] / (fabs(ex) + reg);
  wy[i] = my[i] / (fabs(ey) + reg);
}

// b = Wp P + Dx^T Wx Gx + Dy^T Wy Gy, with (Dx^T v)(x) = v(x-1) - v(x).
__kernel void recon_rhs(__global const float4* P, __global const float4* Gx,
                        __global const float4* Gy, __global const float4* wp,
                        __global const float4* wx, __global const float4* wy, int w, int h,
                        __global float4* b) {
  int i = get_global_id(0);
  if (i >= w * h) return;
  int px = i % w, py = i / w;
  float4 s = wp[i] * P[i] - wx[i] * Gx[i] - wy[i] * Gy[i];
  if (px > 0) s += wx[i - 1] * Gx[i - 1];
  if (py > 0) s += wy[i - w] * Gy[i - w];
  b[i] = s;
}

// 1 / diag(A) for Jacobi smoothing; 0 for a pixel that no term touches.
__kernel void recon_diag_inv(__global const float4* wp, __global const float4* wx,
                             __global const float4* wy, int w, int h, __global float4* dinv) {
  int i = get_global_id(0);
  if (i >= w * h) return;
  int px = i % w, py = i / w;
  float4 d = wp[i] + wx[i] + wy[i];
  if (px > 0) d += wx[i - 1];
  if (py > 0) d += wy[i - w];
  dinv[i] = (float4)(d.x > 0.0f ? 1.0f / d.x : 0.0f, d.y > 0.0f ? 1.0f / d.y : 0.0f,
                     d.z > 0.0f ? 1.0f / d.z : 0.0f, 0.0f);
}

// Per group: the objective sum of |alpha (x - P)| + |dx x - Gx| + |dy x - Gy| over present terms
// (squared terms when l2 != 0). Global size = groups * RECON_LOCAL.
__kernel void recon_energy(__global const float4* x, __global const float4* P,
                           __global const float4* Gx, __global const float4* Gy,
                           __global const float4* mp, __global const float4* mx,
                           __global const float4* my, float alpha, int l2, int w, int h,
                           __global float4* partial) {
  __local float4 scratch[RECON_LOCAL];
  float4 s = (float4)(0.0f);
  RECON_FOR_SHARE(i, w * h) {
    int px = i % w, py = i / w;
    float4 xi = x[i];
    float4 ep = alpha * (xi - P[i]);
    float4 ex = px + 1 < w ? x[i + 1] - xi - Gx[i] : (float4)(0.0f);
    float4 ey = py + 1 < h ? x[i + w] - xi - Gy[i] : (float4)(0.0f);
    if (l2) {
      s += mp[i] * ep * ep + mx[i] * ex * ex + my[i] * ey * ey;
    } else {
      s += mp[i] * fabs(ep) + mx[i] * fabs(ex) + my[i] * fabs(ey);
    }
  }
  float4 total = recon_group_sum(s, scratch);
  if (get_local_id(0) == 0) partial[get_group_id(0)] = total;
}

// float4 planes -> interleaved RGB. The solver never produces non-finite values, but the output
// must be finite whatever happened: fall back to the primal (itself finite after packing).
__kernel void recon_unpack(__global const float4* x, __global const float4* P, int n,
                           __global float* rgb, __global uint* nonfinite) {
  int i = get_global_id(0);
  if (i >= n) return;
  float4 v = x[i], p = P[i];
  float c[3] = {v.x, v.y, v.z}, f[3] = {p.x, p.y, p.z};
  for (int k = 0; k < 3; ++k) {
    if (!isfinite(c[k])) {
      c[k] = f[k];
      atomic_inc(nonfinite);
    }
    rgb[3 * i + k] = c[k];
  }
}
