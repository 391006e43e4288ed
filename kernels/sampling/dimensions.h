// The dimension layout of a path's random numbers, in blocks of four: block 0 for the camera,
// then two per bounce (light sample, BSDF sample + Russian roulette). Every path-based integrator
// reads the same blocks, so gradient-domain shifts replay exactly the numbers the path tracer uses.
// Light subpaths read blocks from RNG_LIGHT_SUBPATH on (two for the emission, then one per
// bounce), so that the camera and light subpaths of one (pixel, sample) never share numbers.
#pragma once

#define RNG_BLOCK_CAMERA 0u
#define RNG_BLOCK_LIGHT(depth) (1u + 2u * (uint)(depth))
#define RNG_BLOCK_BSDF(depth) (2u + 2u * (uint)(depth))

#define RNG_LIGHT_SUBPATH 0x80000000u
#define RNG_BLOCK_EMISSION (RNG_LIGHT_SUBPATH + 0u)      // x: light selection, yz: position
#define RNG_BLOCK_EMISSION_DIR (RNG_LIGHT_SUBPATH + 1u)  // xy: direction
#define RNG_BLOCK_SUBPATH_BSDF(depth) (RNG_LIGHT_SUBPATH + 2u + (uint)(depth))
