// Reads every scene buffer through the parameter list all scene-reading kernels declare
// (SCENE_DATA_ARGS, bound by DeviceScene): buffer b's 32-bit words go to out[offsets[b] ..
// offsets[b + 1]), so the host can compare each word with what it uploaded.
#include "scene/scene_data.h"

__kernel void scene_buffers_copy(SCENE_DATA_ARGS, __global const uint* offsets, __global uint* out) {
  uint i = get_global_id(0);
  uint b = 0;
#define GDR_COPY_WORD(ktype, htype, name, what)                                         \
  if (i >= offsets[b] && i < offsets[b + 1]) out[i] = ((__global const uint*)name)[i - offsets[b]]; \
  ++b;
  GDR_SCENE_BUFFERS(GDR_COPY_WORD, GDR_COPY_WORD)
#undef GDR_COPY_WORD
}
