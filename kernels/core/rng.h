// Counter-based random numbers: Philox4x32-10 (Salmon et al. 2011) keyed by the render seed,
// with the counter (pixel, sample index, block of 4 dimensions). Any (seed, pixel, sample,
// dimension) gives the same number on every device, so a shift can replay a path exactly.
#pragma once

#define GDR_PHILOX_M0 0xD2511F53u
#define GDR_PHILOX_M1 0xCD9E8D57u
#define GDR_PHILOX_W0 0x9E3779B9u
#define GDR_PHILOX_W1 0xBB67AE85u

// One 32x32 -> 64-bit product gives both halves. (PoCL's CPU mul_hi(uint) is built from four
// 16-bit products, which made Philox the largest cost of the shading kernels.)
inline uint2 philox_mulhilo(uint a, uint b) {
  ulong p = (ulong)a * (ulong)b;
  return (uint2)((uint)(p >> 32), (uint)p);
}

inline uint4 philox4x32_10(uint4 c, uint2 k) {
  for (int i = 0; i < 10; ++i) {
    uint2 p0 = philox_mulhilo(GDR_PHILOX_M0, c.x), p1 = philox_mulhilo(GDR_PHILOX_M1, c.z);
    uint hi0 = p0.x, lo0 = p0.y, hi1 = p1.x, lo1 = p1.y;
    c = (uint4)(hi1 ^ c.y ^ k.x, lo1, hi0 ^ c.w ^ k.y, lo0);
    k += (uint2)(GDR_PHILOX_W0, GDR_PHILOX_W1);
  }
  return c;
}

// 24-bit mantissa: uniform in [0, 1), never 1.
inline float rng_to_unit(uint x) { return (float)(x >> 8) * 0x1.0p-24f; }

// Four uniforms for dimensions 4*block .. 4*block+3 of (pixel, sample).
inline float4 rng_block(uint seed, uint pixel, uint sample, uint block) {
  uint4 r = philox4x32_10((uint4)(pixel, sample, block, 0x67647266u /* "gdrf" */), (uint2)(seed, 0x5eedu));
  return (float4)(rng_to_unit(r.x), rng_to_unit(r.y), rng_to_unit(r.z), rng_to_unit(r.w));
}

// One uniform for a single dimension (a quarter of a block's work; use rng_block in hot loops).
inline float rng_uniform(uint seed, uint pixel, uint sample, uint dim) {
  float4 b = rng_block(seed, pixel, sample, dim >> 2);
  uint lane = dim & 3u;
  return lane == 0 ? b.x : lane == 1 ? b.y : lane == 2 ? b.z : b.w;
}
