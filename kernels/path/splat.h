// Splatting: a contribution that may land on any pixel (a light subpath vertex seen by the
// camera) is written to its path's own slot, and path_splat_gather adds the slots into the film
// afterwards. OpenCL 1.2 has no float atomics, and atomics would add in whatever order the work
// items ran: here the slots are sorted by film row (the device sort by key, stable), and every
// pixel is written by one work item only (its row's), which walks the nearby rows' slots in
// order, so the sum's rounding is the same on every run and device.
#pragma once
#include "camera/importance.h"
#include "shared/splat_types.h"

inline void splat_write(__global GdrSplat* s, float2 raster, float3 value) {
  s->raster[0] = raster.x;
  s->raster[1] = raster.y;
  vstore3(value, 0, s->value);
  s->valid = 1;
  s->primal = 1.0f;
}

inline void splat_drop(__global GdrSplat* s) { s->valid = 0; }

// The slot's sort key: the film row holding it (clamped to the image), or past the rows when
// the slot is empty.
__kernel void path_splat_keys(__global const GdrCamera* camera, uint count, __global const GdrSplat* splats,
                              __global uint* keys) {
  uint k = get_global_id(0);
  if (k >= count) return;
  int h = camera->height;
  keys[k] = splats[k].valid ? (uint)clamp((int)floor(splats[k].raster[1]), 0, h - 1) : 0xFFFFFFFFu;
}

// Work item y adds to film row y the slots listed by row (sorted[starts[r], starts[r + 1]): the
// slots of row r in slot order) from the rows whose footprints can reach it, each slot's value
// times each pixel's normalized filter at the slot's film position (camera_pixel_weight). Every
// pixel is written by one work item, which adds in (row, slot) order: the same sum, rounding
// included, on every run and device.
__kernel void path_splat_gather(__global const GdrCamera* camera, __global const uint* starts,
                                __global const uint* sorted, __global const GdrSplat* splats,
                                __global float4* film) {
  int y = (int)get_global_id(0);
  GdrCamera cam = *camera;
  if (y >= cam.height) return;
  float full = camera_filter_full_mass(&cam);
  int reach = (int)ceil(cam.filter_radius) + 1;  // a slot of row r covers rows r - reach .. r + reach
  for (int r = max(y - reach, 0); r <= min(y + reach, cam.height - 1); ++r) {
    for (uint i = starts[r], end = starts[r + 1]; i < end; ++i) {
      uint k = sorted[i];
      float2 raster = (float2)(splats[k].raster[0], splats[k].raster[1]);
      int2 lo, hi;
      camera_pixel_footprint(&cam, raster, &lo, &hi);
      if (y < lo.y || y > hi.y) continue;
      float wy = camera_axis_weight_full(&cam, y, cam.height, raster.y, full);
      if (!(wy > 0.0f)) continue;
      float3 v = vload3(0, splats[k].value) * wy;
      for (int x = lo.x; x <= hi.x; ++x) {
        float wx = camera_axis_weight_full(&cam, x, cam.width, raster.x, full);
        if (wx > 0.0f) film[y * cam.width + x] += (float4)(v * wx, 0.0f);
      }
    }
  }
}
