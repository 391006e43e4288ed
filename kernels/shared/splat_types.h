// A contribution to a film position, for the splat film (engine/render/splat_film.h): written by
// the path that found it into its own slot, gathered into the pixels around it later.
#pragma once

typedef struct GdrSplat {
  float raster[2];  // film position in pixels from the top-left corner
  float value[3];   // what it adds, times each pixel's normalized filter there
  int valid;        // 0: the slot holds nothing (no contribution, or its shadow ray was blocked)
  float primal;     // G-BDPT's light tracing: its primal's weight over value's own (gbidir/light_tracing.h)
  int pad0;         // 32 bytes: clEnqueueFillBuffer's pattern must be a power of two in size
} GdrSplat;
