// Direct solve of the screened Poisson system with uniform weights,
//   (alpha^2 I + Dx^T Dx + Dy^T Dy) x = b   (forward differences, no edge across the border),
// which the DCT-II along y turns into one tridiagonal system along x per y frequency k:
//   (alpha^2 + 4 sin^2(pi k / 2h)) I + Dx^T Dx.
// The DCT of each column is Makhoul's: reorder (even samples forward, odd ones backward), a
// complex FFT of length h (mixed-radix Stockham, one launch per radix stage), and a twist.
// Inside the transform the three channels travel together as one float4 per pixel, row-major
// (w x h, no gaps); complex planes are a real and an imaginary plane of that layout, so
// neighbouring work items (columns) touch neighbouring words. Only load and store see the planar
// layout of grid.h.
#include "recon/grid.h"

// tw[m] = exp(-2 pi i m / n) for m < n.
__kernel void dct_twiddles(int n, __global float2* tw) {
  int m = get_global_id(0);
  if (m >= n) return;
  float t = (float)(2 * m) / (float)n;
  tw[m] = (float2)(cospi(t), -sinpi(t));
}

// The sample of a column that lands at position j of Makhoul's reordering.
RECON_INLINE int dct_source_row(int j, int h) {
  return j < (h + 1) / 2 ? 2 * j : 2 * (h - 1 - j) + 1;
}

// re = reordered b (b in the planar layout of grid.h), im = 0. 2D launch over (column, j).
__kernel void dct_load(__global const float* b, int w, int h, int ws, __global float4* re,
                       __global float4* im) {
  int x = get_global_id(0), j = get_global_id(1);
  if (x >= w || j >= h) return;
  int e = dct_source_row(j, h) * ws + x;
  re[j * w + x] = (float4)(b[gdr_recon_plane(0, ws, h) + e], b[gdr_recon_plane(1, ws, h) + e],
                           b[gdr_recon_plane(2, ws, h) + e], 0.0f);
  im[j * w + x] = (float4)(0.0f);
}

// Largest radix of the generic (O(p^2)) butterfly; the host only picks sizes whose prime factors
// are at most this.
#define DCT_MAX_RADIX 64

// A radix-p Stockham stage of a length-n FFT along y, all columns at once: butterfly i of column
// x reads rows i + j n/p, twists input j by exp(sign 2 pi i j k / (L p)) (k = i mod L, L = the
// product of the radices before), transforms, and writes output q to row (i - k) p + k + q L.
// sign is -1 (forward) or +1 (inverse, unnormalised). 2D launch over (column, i < n/p). The
// radices 2, 3, 4, 5 have their own kernels with the butterfly written out (no private arrays).
#define DCT_STAGE_ARGS                                                                     \
  __global const float4 *in_re, __global const float4 *in_im, __global float4 *out_re,    \
      __global float4 *out_im, __global const float2 *tw, int w, int n, int L, float sign
#define DCT_STAGE_BEGIN(P)                                        \
  int x = get_global_id(0), i = get_global_id(1);                 \
  int m = n / (P);                                                \
  if (x >= w || i >= m) return;                                   \
  int k = i % L;                                                  \
  int step = n / (L * (P));                                       \
  int base = (i - k) * (P) + k;
// Input j of the butterfly, twisted.
#define DCT_IN(j, re, im)                                        \
  float4 re = in_re[(i + (j) * m) * w + x];                      \
  float4 im = in_im[(i + (j) * m) * w + x];                      \
  if ((j) > 0 && k > 0) {                                        \
    float2 t = tw[(j) * k * step];                               \
    float4 tr = re * t.x + im * sign * t.y;                      \
    im = im * t.x - re * sign * t.y;                             \
    re = tr;                                                     \
  }
#define DCT_OUT(q, re, im)                   \
  out_re[(base + (q) * L) * w + x] = (re);   \
  out_im[(base + (q) * L) * w + x] = (im);

__kernel void dct_fft_stage2(DCT_STAGE_ARGS) {
  DCT_STAGE_BEGIN(2)
  DCT_IN(0, r0, i0)
  DCT_IN(1, r1, i1)
  DCT_OUT(0, r0 + r1, i0 + i1)
  DCT_OUT(1, r0 - r1, i0 - i1)
}

__kernel void dct_fft_stage3(DCT_STAGE_ARGS) {
  DCT_STAGE_BEGIN(3)
  DCT_IN(0, r0, i0)
  DCT_IN(1, r1, i1)
  DCT_IN(2, r2, i2)
  // exp(sign 2 pi i / 3) = -1/2 + sign i sqrt(3)/2.
  const float h = 0.86602540378443864676f * sign;
  float4 ar = r0 - 0.5f * (r1 + r2), ai = i0 - 0.5f * (i1 + i2);
  float4 br = -h * (i1 - i2), bi = h * (r1 - r2);  // sign i sqrt(3)/2 (u1 - u2)
  DCT_OUT(0, r0 + r1 + r2, i0 + i1 + i2)
  DCT_OUT(1, ar + br, ai + bi)
  DCT_OUT(2, ar - br, ai - bi)
}

__kernel void dct_fft_stage4(DCT_STAGE_ARGS) {
  DCT_STAGE_BEGIN(4)
  DCT_IN(0, r0, i0)
  DCT_IN(1, r1, i1)
  DCT_IN(2, r2, i2)
  DCT_IN(3, r3, i3)
  float4 ar = r0 + r2, ai = i0 + i2, br = r0 - r2, bi = i0 - i2;
  float4 cr = r1 + r3, ci = i1 + i3, dr = r1 - r3, di = i1 - i3;
  float4 er = -sign * di, ei = sign * dr;  // exp(sign i pi / 2) d = sign i d
  DCT_OUT(0, ar + cr, ai + ci)
  DCT_OUT(1, br + er, bi + ei)
  DCT_OUT(2, ar - cr, ai - ci)
  DCT_OUT(3, br - er, bi - ei)
}

__kernel void dct_fft_stage5(DCT_STAGE_ARGS) {
  DCT_STAGE_BEGIN(5)
  DCT_IN(0, r0, i0)
  DCT_IN(1, r1, i1)
  DCT_IN(2, r2, i2)
  DCT_IN(3, r3, i3)
  DCT_IN(4, r4, i4)
  const float c1 = 0.30901699437494742410f, c2 = -0.80901699437494742410f;
  const float s1 = 0.95105651629515357212f * sign, s2 = 0.58778525229247312917f * sign;
  float4 a1r = r1 + r4, a1i = i1 + i4, b1r = r1 - r4, b1i = i1 - i4;
  float4 a2r = r2 + r3, a2i = i2 + i3, b2r = r2 - r3, b2i = i2 - i3;
  float4 p1r = r0 + c1 * a1r + c2 * a2r, p1i = i0 + c1 * a1i + c2 * a2i;
  float4 p2r = r0 + c2 * a1r + c1 * a2r, p2i = i0 + c2 * a1i + c1 * a2i;
  // i (s1 b1 + s2 b2) and i (s2 b1 - s1 b2), sign folded into s1, s2.
  float4 q1r = -(s1 * b1i + s2 * b2i), q1i = s1 * b1r + s2 * b2r;
  float4 q2r = -(s2 * b1i - s1 * b2i), q2i = s2 * b1r - s1 * b2r;
  DCT_OUT(0, r0 + a1r + a2r, i0 + a1i + a2i)
  DCT_OUT(1, p1r + q1r, p1i + q1i)
  DCT_OUT(4, p1r - q1r, p1i - q1i)
  DCT_OUT(2, p2r + q2r, p2i + q2i)
  DCT_OUT(3, p2r - q2r, p2i - q2i)
}

// Any other radix p <= DCT_MAX_RADIX by the plain O(p^2) DFT.
__kernel void dct_fft_stage(DCT_STAGE_ARGS, int p) {
  DCT_STAGE_BEGIN(p)
  float4 ur[DCT_MAX_RADIX], ui[DCT_MAX_RADIX];
  for (int j = 0; j < p; ++j) {
    DCT_IN(j, re, im)
    ur[j] = re;
    ui[j] = im;
  }
  int pstep = n / p;  // table stride of exp(-2 pi i / p)
  for (int q = 0; q < p; ++q) {
    float4 sr = ur[0], si = ui[0];
    for (int j = 1; j < p; ++j) {
      float2 t = tw[((j * q) % p) * pstep];
      float ty = -sign * t.y;  // the imaginary part for this direction
      sr += ur[j] * t.x - ui[j] * ty;
      si += ur[j] * ty + ui[j] * t.x;
    }
    DCT_OUT(q, sr, si)
  }
}

// Row k of the DCT (the twist Re(exp(-i pi k / 2h) V_k) of the FFT V), then the tridiagonal
// system ((alpha^2 + lambda_k) I + Dx^T Dx) y = X along the row by the Thomas algorithm; the
// system is diagonally dominant by alpha^2 + lambda_k > 0. The forward sweep keeps c' in the
// unused fourth lane. One item per row.
__kernel void dct_solve_rows(__global const float4* re, __global const float4* im, int w, int h,
                             float alpha2, __global float4* y) {
  int k = get_global_id(0);
  if (k >= h) return;
  float turn = (float)k / (float)(2 * h);
  float c = cospi(turn), s = sinpi(turn);
  float shift = alpha2 + 4.0f * s * s;
  __global const float4* rr = re + k * w;
  __global const float4* ri = im + k * w;
  __global float4* yr = y + k * w;
  if (w == 1) {
    yr[0] = (float4)((c * rr[0] + s * ri[0]).xyz / shift, 0.0f);
    return;
  }
  float cp = 0.0f;  // c'_{i-1}
  float4 dp = (float4)(0.0f);
  for (int i = 0; i < w; ++i) {
    float diag = shift + (i == 0 || i == w - 1 ? 1.0f : 2.0f);
    float den = diag + cp;  // diag - (-1) c'_{i-1}
    float4 d = c * rr[i] + s * ri[i];
    dp = (d + dp) / den;
    cp = -1.0f / den;
    yr[i] = (float4)(dp.xyz, cp);
  }
  float4 next = (float4)(0.0f);
  for (int i = w - 1; i >= 0; --i) {
    float4 v = yr[i];
    next = (float4)(v.xyz - v.w * next.xyz, 0.0f);
    yr[i] = next;
  }
}

// The inverse DCT's input to the FFT: V_k = exp(i pi k / 2h) (Y_k - i Y_{h-k}), Y_h = 0.
// 2D launch over (column, k).
__kernel void dct_inverse_load(__global const float4* y, int w, int h, __global float4* re,
                               __global float4* im) {
  int x = get_global_id(0), k = get_global_id(1);
  if (x >= w || k >= h) return;
  float turn = (float)k / (float)(2 * h);
  float c = cospi(turn), s = sinpi(turn);
  float4 a = y[k * w + x];
  float4 b = k > 0 ? y[(h - k) * w + x] : (float4)(0.0f);
  re[k * w + x] = c * a + s * b;
  im[k * w + x] = s * a - c * b;
}

// x = the real part of the inverse FFT, undoing the reordering, scaled by 1/h (x in the planar
// layout of grid.h).
__kernel void dct_store(__global const float4* re, int w, int h, int ws, __global float* x) {
  int col = get_global_id(0), j = get_global_id(1);
  if (col >= w || j >= h) return;
  float4 v = re[j * w + col] / (float)h;
  int e = dct_source_row(j, h) * ws + col;
  x[gdr_recon_plane(0, ws, h) + e] = v.x;
  x[gdr_recon_plane(1, ws, h) + e] = v.y;
  x[gdr_recon_plane(2, ws, h) + e] = v.z;
}
