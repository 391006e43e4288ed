// Where the gradient integrators' extra camera samples of the seen emission go (--direct-samples):
// a pixel's flags say what its samples so far saw. Every pixel takes them until a pass has seen
// it; then those near an emitter's edge, where the direct layer's noise lies: the pixels whose
// 3 x 3 neighbourhood has samples that saw emission and samples that missed it (a pixel that an
// edge barely crosses may not have seen the emitter yet, but its neighbour has). Each pass's
// choice rests on earlier passes only, so each pass's estimate stays unbiased.
#pragma once
#include "shared/pt_types.h"

#define SEEN_FLAG_KNOWN 1u   // a pass has seen the pixel
#define SEEN_FLAG_HIT 2u     // a sample saw emission
#define SEEN_FLAG_MISSED 4u  // a sample saw none

// The flags after a pass whose `samples` camera samples of the pixel saw emission `hits` times.
inline uint seen_flags_after(uint flags, float hits, float samples) {
  return flags | SEEN_FLAG_KNOWN | (hits > 0.0f ? SEEN_FLAG_HIT : 0u) | (hits < samples ? SEEN_FLAG_MISSED : 0u);
}

// Lists the pixels that take extra samples this pass (in no fixed order: each is shaded alone)
// and marks them in `taking` for the gather.
__kernel void seen_list(int width, int height, __global const uint* flags, __global uint* taking,
                        __global uint* list, __global uint* counters) {
  uint p = get_global_id(0);
  if (p >= (uint)(width * height)) return;
  int x = (int)(p % (uint)width), y = (int)(p / (uint)width);
  uint around = 0u;
  for (int ny = max(y - 1, 0); ny <= min(y + 1, height - 1); ++ny) {
    for (int nx = max(x - 1, 0); nx <= min(x + 1, width - 1); ++nx) around |= flags[ny * width + nx];
  }
  int edge = (around & SEEN_FLAG_HIT) && (around & SEEN_FLAG_MISSED);
  uint take = !(flags[p] & SEEN_FLAG_KNOWN) || edge;
  taking[p] = take;
  if (take) list[atomic_inc(&counters[SEEN_COUNTER_LISTED])] = p;
}
