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

// sin(pi y) and cos(pi y) for |y| <= 1/4 by their Taylor series to the ninth power (error below
// 4e-7): cospi and sinpi are calls on PoCL.
inline void probe_sincospi_quarter(float y, float* s, float* c) {
  float x = M_PI_F * y, x2 = x * x;
  *s = x * (1.0f + x2 * (-1.0f / 6.0f + x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 * (1.0f / 362880.0f)))));
  *c = 1.0f + x2 * (-0.5f + x2 * (1.0f / 24.0f + x2 * (-1.0f / 720.0f + x2 * (1.0f / 40320.0f))));
}

// in: the normal's x, y, z, then the throughput's r, g, b; out: the direction, then the throughput.
__kernel void bounce_soa(uint n, uint seed, __global const float* in, __global float* out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  // rng_block(seed, i, 0, 0), word by word.
  uint w0 = i, w1 = 0u, w2 = 0u, w3 = 0x67647266u;
  philox4x32_10_words(&w0, &w1, &w2, &w3, seed, 0x5eedu);
  float u0 = rng_to_unit(w0), u1 = rng_to_unit(w1), u2 = rng_to_unit(w2);

  // square_to_uniform_disk_concentric with selects for its branches; phi in units of pi.
  float x = 2.0f * u0 - 1.0f, y = 2.0f * u1 - 1.0f;
  int wide = fabs(x) > fabs(y);
  float r = wide ? x : y, ratio = (wide ? y : x) / (r == 0.0f ? 1.0f : r);
  float phi = wide ? 0.25f * ratio : 0.5f - 0.25f * ratio;  // within [-1/4, 3/4]
  int far = phi > 0.25f;
  float s, c;
  probe_sincospi_quarter(far ? 0.5f - phi : phi, &s, &c);
  float lx = r * (far ? s : c), ly = r * (far ? c : s);
  float lz = sqrt(fmax(1.0f - lx * lx - ly * ly, 0.0f));

  // frame_from_normal and frame_to_world.
  float n0 = in[i], n1 = in[n + i], n2 = in[2 * n + i];
  float sign = n2 >= 0.0f ? 1.0f : -1.0f, a = -1.0f / (sign + n2), b = n0 * n1 * a;
  out[i] = (1.0f + sign * n0 * n0 * a) * lx + b * ly + n0 * lz;
  out[n + i] = sign * b * lx + (sign + n1 * n1 * a) * ly + n1 * lz;
  out[2 * n + i] = -sign * n0 * lx - n1 * ly + n2 * lz;

  float br = in[3 * n + i] * PROBE_R, bg = in[4 * n + i] * PROBE_G, bb = in[5 * n + i] * PROBE_B;
  float q = fmin(fmax(br, fmax(bg, bb)), 0.95f), k = u2 < q ? 1.0f / q : 0.0f;
  out[3 * n + i] = br * k;
  out[4 * n + i] = bg * k;
  out[5 * n + i] = bb * k;
}

// Philox-4x32-10 on eight counters at once: vector mul_hi here, where the scalar form (core/rng.h)
// needs 64-bit products.
inline void probe_philox8(uint8* w0, uint8* w1, uint8* w2, uint8* w3, uint k0, uint k1) {
  uint8 c0 = *w0, c1 = *w1, c2 = *w2, c3 = *w3;
#pragma unroll
  for (int i = 0; i < 10; ++i) {
    uint8 hi0 = mul_hi(c0, (uint8)GDR_PHILOX_M0), lo0 = c0 * GDR_PHILOX_M0;
    uint8 hi1 = mul_hi(c2, (uint8)GDR_PHILOX_M1), lo1 = c2 * GDR_PHILOX_M1;
    c0 = hi1 ^ c1 ^ k0;
    c1 = lo1;
    c2 = hi0 ^ c3 ^ k1;
    c3 = lo0;
    k0 += GDR_PHILOX_W0;
    k1 += GDR_PHILOX_W1;
  }
  *w0 = c0, *w1 = c1, *w2 = c2, *w3 = c3;
}

inline void probe_sincospi_quarter8(float8 y, float8* s, float8* c) {
  float8 x = M_PI_F * y, x2 = x * x;
  *s = x * (1.0f + x2 * (-1.0f / 6.0f + x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 * (1.0f / 362880.0f)))));
  *c = 1.0f + x2 * (-0.5f + x2 * (1.0f / 24.0f + x2 * (-1.0f / 720.0f + x2 * (1.0f / 40320.0f))));
}

// bounce_soa's numbers for items 8 g .. 8 g + 7 (n a multiple of 8); buffers as bounce_soa's.
__kernel void bounce_lanes(uint n, uint seed, __global const float* in, __global float* out) {
  uint g = get_global_id(0);
  if (g >= n / 8) return;
  uint i = 8 * g;
  uint8 w0 = (uint8)(i) + (uint8)(0, 1, 2, 3, 4, 5, 6, 7), w1 = 0u, w2 = 0u, w3 = 0x67647266u;
  probe_philox8(&w0, &w1, &w2, &w3, seed, 0x5eedu);
  float8 u0 = convert_float8(w0 >> 8) * 0x1.0p-24f, u1 = convert_float8(w1 >> 8) * 0x1.0p-24f,
         u2 = convert_float8(w2 >> 8) * 0x1.0p-24f;

  float8 x = 2.0f * u0 - 1.0f, y = 2.0f * u1 - 1.0f;
  int8 wide = fabs(x) > fabs(y);
  float8 r = select(y, x, wide), ratio = select(x, y, wide) / select(r, (float8)(1.0f), r == 0.0f);
  float8 phi = select(0.5f - 0.25f * ratio, 0.25f * ratio, wide);
  int8 far = phi > 0.25f;
  float8 s, c;
  probe_sincospi_quarter8(select(phi, 0.5f - phi, far), &s, &c);
  float8 lx = r * select(c, s, far), ly = r * select(s, c, far);
  float8 lz = sqrt(fmax(1.0f - lx * lx - ly * ly, 0.0f));

  float8 n0 = vload8(0, in + i), n1 = vload8(0, in + n + i), n2 = vload8(0, in + 2 * n + i);
  float8 sign = select((float8)(-1.0f), (float8)(1.0f), n2 >= 0.0f), a = -1.0f / (sign + n2), b = n0 * n1 * a;
  vstore8((1.0f + sign * n0 * n0 * a) * lx + b * ly + n0 * lz, 0, out + i);
  vstore8(sign * b * lx + (sign + n1 * n1 * a) * ly + n1 * lz, 0, out + n + i);
  vstore8(-sign * n0 * lx - n1 * ly + n2 * lz, 0, out + 2 * n + i);

  float8 br = vload8(0, in + 3 * n + i) * PROBE_R, bg = vload8(0, in + 4 * n + i) * PROBE_G,
         bb = vload8(0, in + 5 * n + i) * PROBE_B;
  float8 q = fmin(fmax(br, fmax(bg, bb)), 0.95f), k = select((float8)(0.0f), 1.0f / q, u2 < q);
  vstore8(br * k, 0, out + 3 * n + i);
  vstore8(bg * k, 0, out + 4 * n + i);
  vstore8(bb * k, 0, out + 5 * n + i);
}
