// pt_generate_lanes: pt_generate eight pixels a work item, for CPU devices (as
// pt_shade_lanes_diffuse): the camera blocks' Philox and the gaussian filter's common case on
// float8 lanes, the rest (other filters, cut pixels, the ray and the writes) lane by lane through
// the scalar helpers. Included by pt.cl.
#pragma once
#include "camera/filter_lanes.h"
#include "core/lanes.h"

__kernel void pt_generate_lanes(__global const GdrCamera* camera, GdrPtParams params, __global GdrRayHit* rays,
                                __global uint* queue, __global GdrPathState* paths) {
  uint base = get_global_id(0) * LANES;
  if (base >= params.pixel_count) return;
  GdrCamera cam = *camera;
  uint8 pixel8 = (uint8)(params.first_pixel + base) + (uint8)(0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u);
  // sampler_camera_ray's numbers (no primary samples): the camera block of each pixel's sample.
  RngBlockLanes u = rng_block_lanes(params.seed, pixel8, (uint8)(params.sample), (uint8)(RNG_BLOCK_CAMERA));
  float ux[LANES], uy[LANES], jx[LANES], jy[LANES];
  int served_x[LANES], served_y[LANES];
  vstore8(u.x, 0, ux);
  vstore8(u.y, 0, uy);
  int8 sx = (int8)(0), sy = (int8)(0);
  if (cam.filter == FILTER_GAUSSIAN) {
    vstore8(gaussian_uncut_offset_lanes(cam.filter_radius, u.x, &sx), 0, jx);
    vstore8(gaussian_uncut_offset_lanes(cam.filter_radius, u.y, &sy), 0, jy);
  }
  vstore8(sx, 0, served_x);
  vstore8(sy, 0, served_y);
  float r = cam.filter_radius;
  for (int k = 0; k < LANES; ++k) {
    uint i = base + (uint)k;
    if (i >= params.pixel_count) break;
    uint pixel = params.first_pixel + i;
    int px = (int)(pixel % (uint)cam.width), py = (int)(pixel / (uint)cam.width);
    float2 rx = filter_range(&cam, px, cam.width), ry = filter_range(&cam, py, cam.height);
    if (!(served_x[k] && rx.x == -r && rx.y == r)) jx[k] = sample_filter_axis(cam.filter, r, rx, ux[k]);
    if (!(served_y[k] && ry.x == -r && ry.y == r)) jy[k] = sample_filter_axis(cam.filter, r, ry, uy[k]);
    CameraRay ray = camera_sample(&cam, px, py, (float2)(jx[k], jy[k]));
    write_camera_ray(&rays[i], &ray, i);
    queue[i] = i;
    paths[i] = path_start(pixel, params.sample);
  }
}
