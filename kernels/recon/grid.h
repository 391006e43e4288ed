// Shared by the reconstruction kernels. An image lives on the device as three planes of one float
// per pixel (R, G, B), stacked in one buffer with gaps between them (shared/recon_layout.h):
//   element (c, x, y) = ws * (1 + c * (h + 1) + y) + x.
// The columns past the width and the rows between planes (one above each plane, one below the
// last) are gap: every term weight is zero there, so the operator needs no border tests, a
// pixel's left neighbour on the row above is harmless, and the three channels never mix. Vectors
// start at zero in the gap and stay finite (the multigrid correction may leave values there,
// which zero weights keep away from the pixels). Absent inputs, including the gap, are stored as
// NaN: see recon_pack.
//
// A work item takes a chunk of RECON_VEC consecutive floats of one plane. On CPU devices chunks are
// 16 wide and written as float16 vector operations (PoCL does not vectorise these kernels across
// work items by itself); on GPUs a chunk is one float and neighbouring items touch neighbouring
// words. Kernels over chunks are launched 2D: (chunk of the plane, channel).
#pragma once
#include "shared/recon_layout.h"

// Helpers are inlined always: PoCL otherwise keeps the larger ones as calls that pass float16
// values through memory.
#define RECON_INLINE inline __attribute__((always_inline))

// Every launch uses this local size (PoCL compiles again per new local size).
#define RECON_LOCAL 64
// Damping of the Jacobi smoother, the usual choice for 5-point stencils; buffers hold the step
// omega / diag(A) rather than the diagonal.
#define RECON_OMEGA 0.8f

#ifndef RECON_VEC
#define RECON_VEC 1
#endif

#if RECON_VEC == 16
typedef float16 floatv;
// Vectors at any float-aligned address, each one unaligned vector access (PoCL's vload16 and
// vload8 assemble the vector from 8-byte pieces).
typedef float16 recon_float16_unaligned __attribute__((aligned(4)));
typedef float8 recon_float8_unaligned __attribute__((aligned(4)));
#define VLOAD(p) (*(__global const recon_float16_unaligned*)(p))
#define VSTORE(v, p) (*(__global recon_float16_unaligned*)(p) = (v))
#define VLOAD8(p) (*(__global const recon_float8_unaligned*)(p))
#define VSTORE8(v, p) (*(__global recon_float8_unaligned*)(p) = (v))
RECON_INLINE float recon_hsum(float16 v) {
  float8 a = v.lo + v.hi;
  float4 b = a.lo + a.hi;
  return b.x + b.y + b.z + b.w;
}
#elif RECON_VEC == 1
typedef float floatv;
#define VLOAD(p) (*(p))
#define VSTORE(v, p) (*(p) = (v))
#define recon_hsum(v) (v)
#else
#error "RECON_VEC must be 1 or 16"
#endif
#if GDR_RECON_ALIGN % RECON_VEC != 0
#error "a chunk must not straddle two rows"
#endif

// Chunks in one plane.
RECON_INLINE int recon_chunks(int ws, int h) { return h * ws / RECON_VEC; }

// The chunk of this work item: channel `c`, first element `o`. Returns past the last chunk.
#define RECON_CHUNK(o, c, ws, h)                                 \
  const int c = get_global_id(1);                                \
  if ((int)get_global_id(0) >= recon_chunks(ws, h)) return;      \
  const int o = gdr_recon_plane(c, ws, h) + (int)get_global_id(0) * RECON_VEC;

// Reducing kernels, launched 2D as (groups * RECON_LOCAL, channel): each item takes a share of the
// plane's chunks, a contiguous run where RECON_CONTIGUOUS is defined (CPU devices: one thread
// walks memory in order), interleaved otherwise (GPUs).
#ifdef RECON_CONTIGUOUS
#define RECON_FOR_SHARE(o, c, ws, h)                                                           \
  const int c = get_global_id(1);                                                              \
  for (int o##_n = recon_chunks(ws, h),                                                        \
           o##_len = (o##_n + (int)get_global_size(0) - 1) / (int)get_global_size(0),          \
           o##_k = (int)get_global_id(0) * o##_len, o##_end = min(o##_n, o##_k + o##_len),     \
           o = gdr_recon_plane(c, ws, h) + o##_k * RECON_VEC;                                      \
       o##_k < o##_end; ++o##_k, o += RECON_VEC)
#else
#define RECON_FOR_SHARE(o, c, ws, h)                                                           \
  const int c = get_global_id(1);                                                              \
  for (int o##_n = recon_chunks(ws, h), o##_k = (int)get_global_id(0),                         \
           o = gdr_recon_plane(c, ws, h) + o##_k * RECON_VEC;                                      \
       o##_k < o##_n; o##_k += (int)get_global_size(0),                                        \
           o += (int)get_global_size(0) * RECON_VEC)
#endif

// Absent terms (non-finite inputs, the last column of dx, the last row of dy, the gap) are NaN
// in the packed inputs: their weight is 0 and their value reads as 0.
#define RECON_ABSENT(v) isnan(v)
RECON_INLINE floatv recon_value(floatv v) { return select(v, (floatv)(0.0f), RECON_ABSENT(v)); }
// `weight` where the term `v` is present, else 0.
RECON_INLINE floatv recon_weight(floatv weight, floatv v) {
  return select(weight, (floatv)(0.0f), RECON_ABSENT(v));
}

// The screened Poisson operator A = Wp + Dx^T Wx Dx + Dy^T Wy Dy at one pixel: wp v + the sum over
// its four edges of w_e (v - v_e), from the pixel's own weights wp, wx (edge to the right), wy
// (edge below), the left neighbour's wx and the upper neighbour's wy (weights are zero where an
// edge leaves the image), and v at the pixel and its right, left, lower and upper neighbours.
RECON_INLINE floatv recon_stencil(floatv wp, floatv wx, floatv wy, floatv wx_left, floatv wy_up,
                                  floatv v, floatv v_right, floatv v_left, floatv v_down,
                                  floatv v_up) {
  return wp * v + wx * (v - v_right) + wx_left * (v - v_left) + wy * (v - v_down) +
         wy_up * (v - v_up);
}

// The same with the weights read for the chunk starting at element o.
RECON_INLINE floatv recon_stencil_at(__global const float* wp, __global const float* wx,
                                     __global const float* wy, int o, int ws, floatv v,
                                     floatv v_right, floatv v_left, floatv v_down, floatv v_up) {
  return recon_stencil(VLOAD(wp + o), VLOAD(wx + o), VLOAD(wy + o), VLOAD(wx + o - 1),
                       VLOAD(wy + o - ws), v, v_right, v_left, v_down, v_up);
}

// (A x) at the chunk starting at element o.
RECON_INLINE floatv recon_apply_at(__global const float* x, __global const float* wp,
                                   __global const float* wx, __global const float* wy, int o,
                                   int ws) {
  return recon_stencil_at(wp, wx, wy, o, ws, VLOAD(x + o), VLOAD(x + o + 1), VLOAD(x + o - 1),
                          VLOAD(x + o + ws), VLOAD(x + o - ws));
}

// Sum of `v` over the work-group (dimension 0); every item of the group must call it.
RECON_INLINE float recon_group_sum(float v, __local float* scratch) {
  int l = get_local_id(0);
  scratch[l] = v;
  barrier(CLK_LOCAL_MEM_FENCE);
  for (int s = RECON_LOCAL / 2; s > 0; s >>= 1) {
    if (l < s) scratch[l] += scratch[l + s];
    barrier(CLK_LOCAL_MEM_FENCE);
  }
  float total = scratch[0];
  barrier(CLK_LOCAL_MEM_FENCE);
  return total;
}

// A reducing kernel's group total into partial[channel][group].
#define RECON_WRITE_PARTIAL(s, scratch, partial)                                          \
  {                                                                                       \
    float total_ = recon_group_sum(recon_hsum(s), scratch);                               \
    if (get_local_id(0) == 0)                                                             \
      partial[get_global_id(1) * get_num_groups(0) + get_group_id(0)] = total_;           \
  }

RECON_INLINE float recon_safe_div(float a, float b) {
  float q = b > 0.0f ? a / b : 0.0f;
  return isfinite(q) ? q : 0.0f;
}

// Per-channel scalars (CG step lengths) live in float4 slots, one lane per channel.
RECON_INLINE float recon_lane(float4 v, int c) { return c == 0 ? v.x : c == 1 ? v.y : v.z; }

// Channel c's a / b for the CG step lengths; 0 where b <= 0 (a converged or empty channel).
RECON_INLINE float recon_ratio(__global const float4* scal, int num, int den, int c) {
  return recon_safe_div(recon_lane(scal[num], c), recon_lane(scal[den], c));
}
