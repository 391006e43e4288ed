// The dimension layout of a path's random numbers, in blocks of four: block 0 for the camera,
// then two per bounce (light sample, BSDF sample + Russian roulette). Every path-based integrator
// reads the same blocks, so gradient-domain shifts replay exactly the numbers the path tracer uses.
// Light subpaths read blocks from RNG_LIGHT_SUBPATH on (two for the emission, then one per
// bounce), so that the camera and light subpaths of one (pixel, sample) never share numbers.
// Under multiplexed strategies (Metropolis) a path also reads RNG_BLOCK_STRATEGY: its length and
// which strategy of that length it is sampled by.
#pragma once
#include "shared/sampler_types.h"

#define RNG_BLOCK_CAMERA 0u
#define RNG_BLOCK_LIGHT(depth) (1u + 2u * (depth))
#define RNG_BLOCK_BSDF(depth) (2u + 2u * (depth))

#define RNG_LIGHT_SUBPATH 0x80000000u
#define RNG_BLOCK_EMISSION (RNG_LIGHT_SUBPATH + 0u)      // x: light selection, yz: position
#define RNG_BLOCK_EMISSION_DIR (RNG_LIGHT_SUBPATH + 1u)  // xy: direction
#define RNG_BLOCK_SUBPATH_BSDF(depth) (RNG_LIGHT_SUBPATH + 2u + (uint)(depth))
#define RNG_BLOCK_STRATEGY (RNG_LIGHT_SUBPATH - 1u)  // x: path length, y: strategy
// The gradient-domain integrators' extra camera samples of their direct layer (sample j of a
// pass: render/seen_emission.h) read blocks below the strategy block, which no camera path reaches.
#define RNG_BLOCK_SEEN(j) (RNG_LIGHT_SUBPATH - 2u - (uint)(j))

#define RNG_BLOCK_NOT_HELD 0xFFFFFFFFu

// In primary sample space (Metropolis chains) the blocks lie densely, in the order the path
// lengths first need them (shared/sampler_types.h): the strategy block, camera block 0, light
// blocks 0 and 1 (length 1), then for length n = 2, 3, ...: camera blocks 2n - 3 and 2n - 2 and
// (from n = 3) light block n - 1. Camera paths alone hold the camera's blocks in their order. A
// block past the layout is not held.
inline uint primary_block_index(uint block, const GdrPrimaryLayout* layout) {
  uint i;
  if (layout->camera_only) {
    i = block < RNG_LIGHT_SUBPATH - 1u ? block : RNG_BLOCK_NOT_HELD;
  } else if (block == RNG_BLOCK_STRATEGY) {
    i = 0u;
  } else if (block >= RNG_LIGHT_SUBPATH) {
    uint b = block - RNG_LIGHT_SUBPATH;
    i = b < 2u ? 2u + b : 3u * b + 2u;
  } else if (block == 0u) {
    i = 1u;
  } else {
    uint n = (block + 1u) / 2u + 1u, k = block - (2u * n - 3u);
    i = (n == 2u ? 4u : 3u * n - 3u) + k;
  }
  return i < layout->blocks ? i : RNG_BLOCK_NOT_HELD;
}
