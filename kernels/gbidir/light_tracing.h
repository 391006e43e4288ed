// G-BDPT's light tracing (t = 1): the light subpaths' connections to the camera (bidir/bidir.cl,
// under bdpt's weight over every strategy) are splatted into a film of their own during a pass,
// then join each pixel's sums in the layer kept out of the gradients, beside the emission the
// camera sees directly: light tracing is not shifted (gbidir/weights.h).
#pragma once
#include "shared/gpt_types.h"

__kernel void gbdpt_add_light_tracing(uint pixels, __global float4* film, __global float4* acc) {
  uint p = get_global_id(0);
  if (p >= pixels) return;
  acc[p * GPT_ACC_COUNT + GPT_ACC_DIRECT] += film[p];
  film[p] = (float4)(0.0f);
}
