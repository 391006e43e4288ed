// Stratified uniform states for estimating the integral of a target apart from the chains
// (engine/integrators/mlt/metropolis_loop.h: stratified_integral).
#pragma once
#include "camera/camera.h"
#include "mlt/chains.h"
#include "sampling/dimensions.h"

// Fresh uniform states (dimension d of chain c at d * chains + c) for samples that feed no chain:
// the large step of chain c at `iteration` (mlt/mutation.h), with the film position stratified:
// sample i = iteration * chains + c lies in cell i mod (width x height) of the sampled region cut
// into the film's width x height cells, so that whole sweeps over the cells estimate the image's
// sum without its variation across the film.
__kernel void mlt_uniform_states(__global const GdrCamera* camera, GdrPrimaryLayout layout, uint seed,
                                 uint iteration, __global float* states) {
  uint c = get_global_id(0);
  if (c >= layout.chains) return;
  GdrMltParams p;
  p.chains = layout.chains;
  p.dims = 4u * layout.blocks;
  mlt_store_large_step(&p, states, c, seed, c, iteration);
  uint w = (uint)camera->width, h = (uint)camera->height;
  uint cell = (uint)(((ulong)iteration * layout.chains + c) % ((ulong)w * h));
  size_t film = (size_t)(4u * primary_block_index(RNG_BLOCK_CAMERA, &layout)) * layout.chains + c;
  states[film] = ((float)(cell % w) + states[film]) / (float)w;
  states[film + layout.chains] = ((float)(cell / w) + states[film + layout.chains]) / (float)h;
}
