// Counter-based random numbers: Philox4x32-10 (Salmon et al. 2011) keyed by the render seed,
// with the counter (pixel, sample index, block of 4 dimensions). Any (seed, pixel, sample,
// dimension) gives the same number on every device, so a shift can replay a path exactly.
#pragma once

#define GDR_PHILOX_M0 0xD2511F53u
#define GDR_PHILOX_M1 0xCD9E8D57u
#define GDR_PHILOX_W0 0x9E3779B9u
#define GDR_PHILOX_W1 0xBB67AE85u

// Each round takes both halves of its products from one 32x32 -> 64-bit multiply, and the state
// lives in scalars: PoCL's CPU mul_hi(uint) is built from four 16-bit products, and uint4 state
// compiles to lane inserts and extracts, which together made Philox the largest cost of the
// shading kernels. The words come and go by pointer, so that a kernel written for PoCL's
// vectorizer, which rejects any vector-typed value in a work item's code, can use them
// (tests/bench/bench_vectorization.cpp).
__attribute__((always_inline)) inline void philox4x32_10_words(uint* w0, uint* w1, uint* w2, uint* w3, uint k0, uint k1) {
  uint c0 = *w0, c1 = *w1, c2 = *w2, c3 = *w3;
#pragma unroll
  for (int i = 0; i < 10; ++i) {
    ulong p0 = (ulong)GDR_PHILOX_M0 * (ulong)c0, p1 = (ulong)GDR_PHILOX_M1 * (ulong)c2;
    c0 = (uint)(p1 >> 32) ^ c1 ^ k0;
    c1 = (uint)p1;
    c2 = (uint)(p0 >> 32) ^ c3 ^ k1;
    c3 = (uint)p0;
    k0 += GDR_PHILOX_W0;
    k1 += GDR_PHILOX_W1;
  }
  *w0 = c0, *w1 = c1, *w2 = c2, *w3 = c3;
}

__attribute__((always_inline)) inline uint4 philox4x32_10(uint4 c, uint2 k) {
  uint c0 = c.x, c1 = c.y, c2 = c.z, c3 = c.w;
  philox4x32_10_words(&c0, &c1, &c2, &c3, k.x, k.y);
  return (uint4)(c0, c1, c2, c3);
}

// The same on eight counters at once (one per lane, kernels written eight paths a work item):
// vector mul_hi widens where the scalar 64-bit products would not.
__attribute__((always_inline)) inline void philox4x32_10_lanes(uint8* w0, uint8* w1, uint8* w2, uint8* w3, uint k0,
                                                               uint k1) {
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

// The counter's fourth word ("gdrf") and the key's second, beside the seed.
#define GDR_RNG_TAG 0x67647266u
#define GDR_RNG_KEY 0x5eedu
// 24-bit mantissa: uniform in [0, 1), never 1 (CONVERT: convert_float, or a vector's).
#define RNG_TO_UNIT(CONVERT, x) (CONVERT((x) >> 8) * 0x1.0p-24f)
inline float rng_to_unit(uint x) { return RNG_TO_UNIT((float), x); }

// Four uniforms for dimensions 4*block .. 4*block+3 of (pixel, sample).
inline float4 rng_block(uint seed, uint pixel, uint sample, uint block) {
  uint4 r = philox4x32_10((uint4)(pixel, sample, block, GDR_RNG_TAG), (uint2)(seed, GDR_RNG_KEY));
  return (float4)(rng_to_unit(r.x), rng_to_unit(r.y), rng_to_unit(r.z), rng_to_unit(r.w));
}

// rng_block of eight (pixel, sample, block) counters: lane k's four uniforms are (x, y, z, w)[k].
typedef struct {
  float8 x, y, z, w;
} RngBlockLanes;

__attribute__((always_inline)) inline RngBlockLanes rng_block_lanes(uint seed, uint8 pixel, uint8 sample, uint8 block) {
  uint8 c0 = pixel, c1 = sample, c2 = block, c3 = (uint8)GDR_RNG_TAG;
  philox4x32_10_lanes(&c0, &c1, &c2, &c3, seed, GDR_RNG_KEY);
  RngBlockLanes r;
  r.x = RNG_TO_UNIT(convert_float8, c0);
  r.y = RNG_TO_UNIT(convert_float8, c1);
  r.z = RNG_TO_UNIT(convert_float8, c2);
  r.w = RNG_TO_UNIT(convert_float8, c3);
  return r;
}

// One uniform for a single dimension (a quarter of a block's work; use rng_block in hot loops).
inline float rng_uniform(uint seed, uint pixel, uint sample, uint dim) {
  float4 b = rng_block(seed, pixel, sample, dim >> 2);
  uint lane = dim & 3u;
  return lane == 0 ? b.x : lane == 1 ? b.y : lane == 2 ? b.z : b.w;
}
