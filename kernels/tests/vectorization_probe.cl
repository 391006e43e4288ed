// One diffuse bounce's sampling (a Philox block, a cosine-weighted direction around the normal,
// Russian roulette on the throughput), written three ways for tests/bench/bench_vectorization.cpp:
//   - bounce_aos: the engine's float3 helpers on float4 (array-of-structures) buffers, as the
//     shading kernels are written;
//   - bounce_soa: the same numbers as scalar code on component-major (structure-of-arrays)
//     buffers: component c of item i at c * n + i.
//   - bounce_lanes: eight items a work item, in float8 and uint8 values.
// PoCL runs a work group as a loop over its work items, which LLVM's loop vectorizer widens (8
// work items to an AVX2 register) only if the loop body holds no value of vector type, no call
// and no inner loop. bounce_aos holds vector values and calls (cospi and sinpi stay library
// calls). bounce_soa has neither in its source and is still refused: PoCL's SLP pass, which runs
// before the loop vectorizer, packs its pairs of like scalar operations (u0 and u1, say) into
// vectors. bounce_lanes does the widening itself.
#include "core/frame.h"
#include "core/geometry.h"
#include "core/lanes.h"
#include "core/rng.h"
#include "core/warp.h"

// The albedo.
#define PROBE_R 0.7f
#define PROBE_G 0.5f
#define PROBE_B 0.3f

__kernel void bounce_aos(uint n, uint seed, __global const float4* normal, __global const float4* throughput,
                         __global float4* dir, __global float4* throughput_out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  float4 u = rng_block(seed, i, 0u, 0u);
  Frame f = frame_from_normal(normal[i].xyz);
  float3 wi = frame_to_world(&f, square_to_cosine_hemisphere(u.xy));
  float3 beta = throughput[i].xyz * (float3)(PROBE_R, PROBE_G, PROBE_B);
  float q = fmin(max3(beta), 0.95f);
  throughput_out[i] = u.z < q ? (float4)(beta / q, 0.0f) : (float4)(0.0f);
  dir[i] = (float4)(wi, 0.0f);
}

// The bounce of the items whose counters are `ids` (the first one i), in values of type F with
// integers I and U: one text for bounce_soa (scalars) and bounce_lanes (eight lanes). Comparisons
// and select() agree on both (select takes its second value where the condition holds).
// square_to_uniform_disk_concentric's branches are selects; phi is in units of pi. Buffers: in
// holds the normal's x, y, z, then the throughput's r, g, b; out the direction, then the throughput.
#define PROBE_BOUNCE(F, I, U, ids, LOAD, STORE, PHILOX, SINCOSPI, CONVERT)                            \
  U w0 = ids, w1 = 0u, w2 = 0u, w3 = GDR_RNG_TAG; /* rng_block(seed, item, 0, 0) */                \
  PHILOX(&w0, &w1, &w2, &w3, seed, GDR_RNG_KEY);                                                     \
  F u0 = RNG_TO_UNIT(CONVERT, w0), u1 = RNG_TO_UNIT(CONVERT, w1), u2 = RNG_TO_UNIT(CONVERT, w2);     \
  F x = 2.0f * u0 - 1.0f, y = 2.0f * u1 - 1.0f;                                                      \
  I wide = fabs(x) > fabs(y);                                                                        \
  F r = select(y, x, wide), ratio = select(x, y, wide) / select(r, (F)(1.0f), r == 0.0f);            \
  F phi = select(0.5f - 0.25f * ratio, 0.25f * ratio, wide); /* within [-1/4, 3/4] */               \
  I far = phi > 0.25f;                                                                               \
  F s, c;                                                                                            \
  SINCOSPI(select(phi, 0.5f - phi, far), &s, &c);                                                    \
  F lx = r * select(c, s, far), ly = r * select(s, c, far);                                          \
  F lz = sqrt(fmax(1.0f - lx * lx - ly * ly, 0.0f));                                                 \
  /* frame_from_normal and frame_to_world */                                                         \
  F n0 = LOAD(in + i), n1 = LOAD(in + n + i), n2 = LOAD(in + 2 * n + i);                             \
  F sign = select((F)(-1.0f), (F)(1.0f), n2 >= 0.0f), a = -1.0f / (sign + n2), b = n0 * n1 * a;      \
  STORE((1.0f + sign * n0 * n0 * a) * lx + b * ly + n0 * lz, out + i);                               \
  STORE(sign * b * lx + (sign + n1 * n1 * a) * ly + n1 * lz, out + n + i);                           \
  STORE(-sign * n0 * lx - n1 * ly + n2 * lz, out + 2 * n + i);                                       \
  F br = LOAD(in + 3 * n + i) * PROBE_R, bg = LOAD(in + 4 * n + i) * PROBE_G,                        \
    bb = LOAD(in + 5 * n + i) * PROBE_B;                                                             \
  F q = fmin(fmax(br, fmax(bg, bb)), 0.95f), k = select((F)(0.0f), 1.0f / q, u2 < q);                \
  STORE(br * k, out + 3 * n + i);                                                                    \
  STORE(bg * k, out + 4 * n + i);                                                                    \
  STORE(bb * k, out + 5 * n + i);

#define PROBE_LOAD1(p) (*(p))
#define PROBE_STORE1(v, p) (*(p) = (v))
#define PROBE_LOAD8(p) vload8(0, p)
#define PROBE_STORE8(v, p) vstore8(v, 0, p)

__kernel void bounce_soa(uint n, uint seed, __global const float* in, __global float* out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  PROBE_BOUNCE(float, int, uint, i, PROBE_LOAD1, PROBE_STORE1, philox4x32_10_words, sincospi_quarter,
               convert_float)
}

// Items 8 g .. 8 g + 7 (n a multiple of 8).
__kernel void bounce_lanes(uint n, uint seed, __global const float* in, __global float* out) {
  uint g = get_global_id(0);
  if (g >= n / 8) return;
  uint i = 8 * g;
  PROBE_BOUNCE(float8, int8, uint8, (uint8)(i) + (uint8)(0, 1, 2, 3, 4, 5, 6, 7), PROBE_LOAD8, PROBE_STORE8,
               philox4x32_10_lanes, sincospi_quarter_lanes, convert_float8)
}
