// The dimension layout of a path's random numbers, in blocks of four: block 0 for the camera,
// then two per bounce (light sample, BSDF sample + Russian roulette). Every path-based integrator
// reads the same blocks, so gradient-domain shifts replay exactly the numbers the path tracer uses.
#pragma once

#define RNG_BLOCK_CAMERA 0u
#define RNG_BLOCK_LIGHT(depth) (1u + 2u * (uint)(depth))
#define RNG_BLOCK_BSDF(depth) (2u + 2u * (uint)(depth))
