// Splatting: a contribution that may land on any pixel (a light subpath vertex seen by the
// camera) is written to its path's own slot, and path_splat_gather adds the slots into the film
// afterwards. OpenCL 1.2 has no float atomics, and atomics would add in whatever order the work
// items ran: here every pixel is written by one work item only (the band of rows holding it),
// which walks the slots in slot order, so the sum's rounding is the same on every run and
// device, whatever the number of bands.
#pragma once
#include "camera/importance.h"
#include "shared/splat_types.h"

#define SPLAT_MAX_SPAN 16

inline void splat_write(__global GdrSplat* s, float2 raster, float3 value) {
  s->raster[0] = raster.x;
  s->raster[1] = raster.y;
  vstore3(value, 0, s->value);
  s->valid = 1;
}

inline void splat_drop(__global GdrSplat* s) { s->valid = 0; }

// Work item b of `bands` adds slots [0, count) to the rows of its band, each slot's value times
// each pixel's normalized filter at the slot's film position (camera_pixel_weight).
__kernel void path_splat_gather(__global const GdrCamera* camera, uint count, uint bands,
                                __global const GdrSplat* splats, __global float4* film) {
  uint b = get_global_id(0);
  if (b >= bands) return;
  GdrCamera cam = *camera;
  int rows = (cam.height + (int)bands - 1) / (int)bands;
  int row_lo = (int)b * rows, row_hi = min(row_lo + rows, cam.height) - 1;
  if (row_lo > row_hi) return;
  float full = camera_filter_full_mass(&cam);
  for (uint k = 0; k < count; ++k) {
    if (!splats[k].valid) continue;
    float2 raster = (float2)(splats[k].raster[0], splats[k].raster[1]);
    int2 lo, hi;
    camera_pixel_footprint(&cam, raster, &lo, &hi);
    int y0 = max(lo.y, row_lo), y1 = min(hi.y, row_hi);
    if (y0 > y1) continue;
    float3 v = vload3(0, splats[k].value);
    // The filter is separable: each column's weight is computed once per slot (footprints up to
    // SPLAT_MAX_SPAN pixels wide; wider ones compute it per pixel).
    int nx = hi.x - lo.x + 1, cached = nx <= SPLAT_MAX_SPAN;
    float wx[SPLAT_MAX_SPAN];
    for (int i = 0; cached && i < nx; ++i) wx[i] = camera_axis_weight_full(&cam, lo.x + i, cam.width, raster.x, full);
    for (int y = y0; y <= y1; ++y) {
      float wy = camera_axis_weight_full(&cam, y, cam.height, raster.y, full);
      if (!(wy > 0.0f)) continue;
      for (int x = lo.x; x <= hi.x; ++x) {
        float w = (cached ? wx[x - lo.x] : camera_axis_weight_full(&cam, x, cam.width, raster.x, full)) * wy;
        if (w > 0.0f) film[y * cam.width + x] += (float4)(v * w, 0.0f);
      }
    }
  }
}
