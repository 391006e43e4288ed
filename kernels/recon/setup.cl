// Problem set-up for the screened Poisson reconstruction: packing and checking the inputs,
// the per-term weights (L2, inverse-variance weighted L2, or IRLS for L1), the right-hand side,
// the Jacobi step, the objective value, and unpacking the result. Layout: grid.h.
#include "recon/grid.h"

// Interleaved RGB primal / dx / dy -> planes; x starts at the primal. P, Gx, Gy arrive filled
// with NaN (absent) and x with 0: a finite input is stored, a non-finite one is counted and stays
// absent. The last column of dx and the last row of dy are no terms at all. 2D launch over pixels.
__kernel void recon_pack(__global const float* primal, __global const float* dx,
                         __global const float* dy, int w, int h, int ws, __global float* P,
                         __global float* Gx, __global float* Gy, __global float* x,
                         __global uint* nonfinite) {
  int px = get_global_id(0), py = get_global_id(1);
  if (px >= w || py >= h) return;
  int i = py * w + px;
  uint bad = 0;
  for (int c = 0; c < 3; ++c) {
    int e = gdr_recon_plane(c, ws, h) + py * ws + px;
    float p = primal[3 * i + c];
    if (isfinite(p)) {
      P[e] = p;
      x[e] = p;
    } else {
      ++bad;
    }
    if (px + 1 < w) {
      float g = dx[3 * i + c];
      if (isfinite(g)) Gx[e] = g; else ++bad;
    }
    if (py + 1 < h) {
      float g = dy[3 * i + c];
      if (isfinite(g)) Gy[e] = g; else ++bad;
    }
  }
  if (bad) atomic_add(nonfinite, bad);
}

// The damped Jacobi step omega / diag(A) from the five weights touching a pixel; 0 where no
// term touches it (and in the gap).
RECON_INLINE floatv recon_jacobi_step(floatv wp, floatv wx, floatv wy, floatv w_left,
                                      floatv w_up) {
  floatv d = wp + wx + wy + w_left + w_up;
  return select((floatv)(0.0f), RECON_OMEGA / d, d > 0.0f);
}

// L2: every present term has weight 1 (alpha^2 for the primal term); and the Jacobi step.
__kernel void recon_weights_l2(__global const float* P, __global const float* Gx,
                               __global const float* Gy, float alpha2, int ws, int h,
                               __global float* wp, __global float* wx, __global float* wy,
                               __global float* step) {
  RECON_CHUNK(o, c, ws, h)
  const floatv one = (floatv)(1.0f);
  floatv wpi = recon_weight((floatv)(alpha2), VLOAD(P + o));
  floatv wxi = recon_weight(one, VLOAD(Gx + o)), wyi = recon_weight(one, VLOAD(Gy + o));
  VSTORE(wpi, wp + o);
  VSTORE(wxi, wx + o);
  VSTORE(wyi, wy + o);
  VSTORE(recon_jacobi_step(wpi, wxi, wyi, recon_weight(one, VLOAD(Gx + o - 1)),
                        recon_weight(one, VLOAD(Gy + o - ws))),
         step + o);
}

// The weighted (generalised least squares) form: a term's weight is inversely proportional to
// the variance estimate v of its input, 1 / (v * inv_scale + floor_rel), with inv_scale the
// inverse of the image's variance scale (0 when the image has no variance at all) and floor_rel
// > 0 the floor relative to it: weights are dimensionless, at most 1 / floor_rel, and a zero
// estimate gives the largest weight instead of an infinite one. A non-finite estimate stands for
// the scale itself (weight 1 / (1 + floor_rel)) and is counted; a negative one reads as 0.
RECON_INLINE float recon_variance_weight(float v, float inv_scale, float floor_rel, uint* bad) {
  if (!isfinite(v)) {
    ++*bad;
    return 1.0f / (1.0f + floor_rel);
  }
  return 1.0f / (fmax(v, 0.0f) * inv_scale + floor_rel);
}

// Term weights of the weighted form from per-pixel variance estimates (interleaved RGB, as the
// primal, dx and dy they belong to), times alpha^2 for the primal term as in the L2 form;
// absent terms keep weight 0. The Jacobi step is left to recon_step. 2D launch over pixels.
__kernel void recon_weights_variance(__global const float* var_p, __global const float* var_x,
                                     __global const float* var_y, int w, int h, int ws,
                                     float4 inv_scale, float floor_rel, float alpha2,
                                     __global const float* P, __global const float* Gx,
                                     __global const float* Gy, __global float* wp,
                                     __global float* wx, __global float* wy,
                                     __global uint* nonfinite) {
  int px = get_global_id(0), py = get_global_id(1);
  if (px >= w || py >= h) return;
  int i = py * w + px;
  uint bad = 0;
  for (int c = 0; c < 3; ++c) {
    int e = gdr_recon_plane(c, ws, h) + py * ws + px;
    float s = recon_lane(inv_scale, c);
    float a = alpha2 * recon_variance_weight(var_p[3 * i + c], s, floor_rel, &bad);
    float b = recon_variance_weight(var_x[3 * i + c], s, floor_rel, &bad);
    float d = recon_variance_weight(var_y[3 * i + c], s, floor_rel, &bad);
    wp[e] = RECON_ABSENT(P[e]) ? 0.0f : a;
    wx[e] = RECON_ABSENT(Gx[e]) ? 0.0f : b;
    wy[e] = RECON_ABSENT(Gy[e]) ? 0.0f : d;
  }
  if (bad) atomic_add(nonfinite, bad);
}

// The Jacobi step from the stored weights.
__kernel void recon_step(__global const float* wp, __global const float* wx,
                         __global const float* wy, int ws, int h, __global float* step) {
  RECON_CHUNK(o, c, ws, h)
  VSTORE(recon_jacobi_step(VLOAD(wp + o), VLOAD(wx + o), VLOAD(wy + o), VLOAD(wx + o - 1),
                           VLOAD(wy + o - ws)),
         step + o);
}

// b = Wp P + Dx^T Wx Gx + Dy^T Wy Gy at one pixel, with (Dx^T v)(x) = v(x-1) - v(x): the weights
// as in recon_stencil, the inputs at the pixel and (gx_left, gy_up) at its left and upper
// neighbours; absent inputs count as 0.
RECON_INLINE floatv recon_rhs_at(floatv wp, floatv wx, floatv wy, floatv wx_left, floatv wy_up,
                                 floatv p, floatv gx, floatv gy, floatv gx_left, floatv gy_up) {
  return wp * recon_value(p) - wx * recon_value(gx) - wy * recon_value(gy) +
         wx_left * recon_value(gx_left) + wy_up * recon_value(gy_up);
}

// The IRLS weight of a term with residual e: 1/(|e| + reg), so that w e^2 ~ |e| at the current
// estimate; 0 for an absent term (g NaN).
RECON_INLINE floatv recon_l1_weight(floatv e, floatv g, float reg) {
  return recon_weight(1.0f / (fabs(e) + reg), g);
}

// L1 by iteratively reweighted least squares: the weights from the current estimate x, and
// everything a solve starts from: b, the Jacobi step and r = b - A x (the left and upper neighbours'
// edge weights recomputed here rather than read back).
__kernel void recon_weights_l1(__global const float* x, __global const float* P,
                               __global const float* Gx, __global const float* Gy, float alpha,
                               float reg, int ws, int h, __global float* wp,
                               __global float* wx, __global float* wy, __global float* step,
                               __global float* b, __global float* r) {
  RECON_CHUNK(o, c, ws, h)
  floatv xi = VLOAD(x + o), p = VLOAD(P + o), gx = VLOAD(Gx + o), gy = VLOAD(Gy + o);
  floatv gl = VLOAD(Gx + o - 1), gu = VLOAD(Gy + o - ws);
  floatv xr = VLOAD(x + o + 1), xl = VLOAD(x + o - 1);
  floatv xd = VLOAD(x + o + ws), xu = VLOAD(x + o - ws);
  floatv wpi = recon_weight(alpha * alpha / (fabs(alpha * (xi - p)) + reg), p);
  floatv wxi = recon_l1_weight(xr - xi - gx, gx, reg);
  floatv wyi = recon_l1_weight(xd - xi - gy, gy, reg);
  floatv wl = recon_l1_weight(xi - xl - gl, gl, reg);
  floatv wu = recon_l1_weight(xi - xu - gu, gu, reg);
  floatv bi = recon_rhs_at(wpi, wxi, wyi, wl, wu, p, gx, gy, gl, gu);
  floatv ax = recon_stencil(wpi, wxi, wyi, wl, wu, xi, xr, xl, xd, xu);
  VSTORE(wpi, wp + o);
  VSTORE(wxi, wx + o);
  VSTORE(wyi, wy + o);
  VSTORE(recon_jacobi_step(wpi, wxi, wyi, wl, wu), step + o);
  VSTORE(bi, b + o);
  VSTORE(bi - ax, r + o);
}

// b from the stored weights (recon_rhs_at).
__kernel void recon_rhs(__global const float* P, __global const float* Gx,
                        __global const float* Gy, __global const float* wp,
                        __global const float* wx, __global const float* wy, int ws, int h,
                        __global float* b) {
  RECON_CHUNK(o, c, ws, h)
  VSTORE(recon_rhs_at(VLOAD(wp + o), VLOAD(wx + o), VLOAD(wy + o), VLOAD(wx + o - 1),
                      VLOAD(wy + o - ws), VLOAD(P + o), VLOAD(Gx + o), VLOAD(Gy + o),
                      VLOAD(Gx + o - 1), VLOAD(Gy + o - ws)),
         b + o);
}

// Per group and channel: the objective sum of |alpha (x - P)| + |dx x - Gx| + |dy x - Gy| over
// present terms (squared terms when l2 != 0). Reducing launch (grid.h).
__kernel void recon_energy(__global const float* x, __global const float* P,
                           __global const float* Gx, __global const float* Gy, float alpha,
                           int l2, int ws, int h, __global float* partial) {
  __local float scratch[RECON_LOCAL];
  floatv s = (floatv)(0.0f);
  RECON_FOR_SHARE(o, c, ws, h) {
    floatv xi = VLOAD(x + o);
    floatv ep = recon_value(alpha * (xi - VLOAD(P + o)));
    floatv ex = recon_value(VLOAD(x + o + 1) - xi - VLOAD(Gx + o));
    floatv ey = recon_value(VLOAD(x + o + ws) - xi - VLOAD(Gy + o));
    s += l2 ? ep * ep + ex * ex + ey * ey : fabs(ep) + fabs(ex) + fabs(ey);
  }
  RECON_WRITE_PARTIAL(s, scratch, partial)
}

// The weighted objective: per group and channel the sum of wp (x - P)^2 + wx (dx x - Gx)^2 +
// wy (dy x - Gy)^2 with the stored weights (absent terms have weight 0). Reducing launch.
__kernel void recon_energy_weighted(__global const float* x, __global const float* P,
                                    __global const float* Gx, __global const float* Gy,
                                    __global const float* wp, __global const float* wx,
                                    __global const float* wy, int ws, int h,
                                    __global float* partial) {
  __local float scratch[RECON_LOCAL];
  floatv s = (floatv)(0.0f);
  RECON_FOR_SHARE(o, c, ws, h) {
    floatv xi = VLOAD(x + o);
    floatv ep = recon_value(xi - VLOAD(P + o));
    floatv ex = recon_value(VLOAD(x + o + 1) - xi - VLOAD(Gx + o));
    floatv ey = recon_value(VLOAD(x + o + ws) - xi - VLOAD(Gy + o));
    s += VLOAD(wp + o) * ep * ep + VLOAD(wx + o) * ex * ex + VLOAD(wy + o) * ey * ey;
  }
  RECON_WRITE_PARTIAL(s, scratch, partial)
}

// Planes -> interleaved RGB. The solver never produces non-finite values, but the output must be
// finite whatever happened: fall back to the primal, else 0. 2D launch over pixels.
__kernel void recon_unpack(__global const float* x, __global const float* P, int w, int h,
                           int ws, __global float* rgb, __global uint* nonfinite) {
  int px = get_global_id(0), py = get_global_id(1);
  if (px >= w || py >= h) return;
  int i = py * w + px;
  for (int c = 0; c < 3; ++c) {
    int e = gdr_recon_plane(c, ws, h) + py * ws + px;
    float v = x[e];
    if (!isfinite(v)) {
      float p = P[e];
      v = isfinite(p) ? p : 0.0f;
      atomic_inc(nonfinite);
    }
    rgb[3 * i + c] = v;
  }
}
