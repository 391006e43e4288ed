// Shared by the reconstruction kernels. Images live on the device as one float4 per pixel
// (R, G, B, unused = 0), row-major from the top row, so every kernel treats the three colour
// channels at once. A term's weights are stored per pixel: wp for the primal term, wx for the
// edge to the right neighbour, wy for the edge to the pixel below (zero on the last column / row:
// no gradient across the image border).
#pragma once

// Every launch uses this local size (PoCL compiles again per new local size).
#define RECON_LOCAL 64

// Each item of a reducing kernel takes a share of the n pixels: a contiguous run where
// RECON_CONTIGUOUS is defined (CPU devices: one thread walks memory in order), interleaved
// otherwise (GPUs: neighbouring items touch neighbouring words).
#ifdef RECON_CONTIGUOUS
#define RECON_FOR_SHARE(i, n)                                                        \
  for (int i##_len = ((n) + (int)get_global_size(0) - 1) / (int)get_global_size(0), \
           i = (int)get_global_id(0) * i##_len, i##_end = min((int)(n), i + i##_len); \
       i < i##_end; ++i)
#else
#define RECON_FOR_SHARE(i, n) \
  for (int i = (int)get_global_id(0); i < (n); i += (int)get_global_size(0))
#endif

// (A x)(i) = wp x_i + sum over the pixel's edges of w_e (x_i - x_j): the screened Poisson
// operator alpha^2 Wp + Dx^T Wx Dx + Dy^T Wy Dy applied at one pixel.
inline float4 recon_apply_at(__global const float4* x, __global const float4* wp,
                             __global const float4* wx, __global const float4* wy, int px, int py,
                             int w, int h) {
  int i = py * w + px;
  float4 xi = x[i];
  float4 s = wp[i] * xi;
  if (px + 1 < w) s += wx[i] * (xi - x[i + 1]);
  if (px > 0) s += wx[i - 1] * (xi - x[i - 1]);
  if (py + 1 < h) s += wy[i] * (xi - x[i + w]);
  if (py > 0) s += wy[i - w] * (xi - x[i - w]);
  return s;
}

// Sum of `v` over the work-group; every item of the group must call it.
inline float4 recon_group_sum(float4 v, __local float4* scratch) {
  int l = get_local_id(0);
  scratch[l] = v;
  barrier(CLK_LOCAL_MEM_FENCE);
  for (int s = RECON_LOCAL / 2; s > 0; s >>= 1) {
    if (l < s) scratch[l] += scratch[l + s];
    barrier(CLK_LOCAL_MEM_FENCE);
  }
  float4 total = scratch[0];
  barrier(CLK_LOCAL_MEM_FENCE);
  return total;
}

inline float recon_safe_div(float a, float b) {
  float q = b > 0.0f ? a / b : 0.0f;
  return isfinite(q) ? q : 0.0f;
}

// Per-channel a / b for the CG step lengths; 0 where b <= 0 (a converged or empty channel).
inline float4 recon_ratio(float4 a, float4 b) {
  return (float4)(recon_safe_div(a.x, b.x), recon_safe_div(a.y, b.y), recon_safe_div(a.z, b.z),
                  0.0f);
}
