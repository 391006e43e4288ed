// The Metropolis integrators' splats (engine/integrators/mlt/metropolis_loop.h): every chain holds
// R contribution records for its current state and R for its proposal (record r of chain c at
// r * chains + c: a film position and the value over the target f), and each step splats both
// with their expected-value weights, record r into its own splat slots (path/splat.h gathers
// them into record r's film layer).
#pragma once
#include "mlt/chains.h"
#include "shared/splat_types.h"

// Record r's splats of chain c into slots 2c (the current state, weight 1 - a) and 2c + 1 (the
// proposal, weight a) from `first`. The launch of the last record then moves the chain's current
// records to its proposal's where mlt_accept accepted (the same uniform).
__kernel void mlt_splat(GdrMltParams p, uint record, uint records, __global const float2* weights,
                        __global GdrSplat* current, __global const GdrSplat* proposed, uint first,
                        __global GdrSplat* slots) {
  uint c = get_global_id(0);
  if (c >= p.chains) return;
  float2 w = weights[c];
  size_t i = (size_t)record * p.chains + c;
  GdrSplat x = current[i], y = proposed[i];
  __global GdrSplat* out = &slots[first + 2 * c];
  out[0] = x;
  out[0].valid = x.valid && w.x > 0.0f;
  vstore3(vload3(0, x.value) * w.x, 0, out[0].value);
  out[1] = y;
  out[1].valid = y.valid && w.y > 0.0f;
  vstore3(vload3(0, y.value) * w.y, 0, out[1].value);
  if (record + 1 < records || !(mlt_control(&p, c).accept < w.y)) return;
  for (uint r = 0; r < records; ++r) current[(size_t)r * p.chains + c] = proposed[(size_t)r * p.chains + c];
}
