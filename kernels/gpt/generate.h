// G-PT: camera rays of the base and its four offsets (the pixel shift), and the filing of
// Embree's answers for the offsets.
#pragma once
#include "camera/camera.h"
#include "core/rng.h"
#include "gpt/common.h"

__kernel void gpt_generate(__global const GdrCamera* camera, GdrGptParams params, __global GdrRayHit* base_rays,
                           __global GdrRayHit* offset_rays, __global GptBaseState* bases,
                           __global GptOffsetState* offsets, __global float4* acc, __global uint* counters) {
  uint g = get_global_id(0);
  if (g >= params.path.pixel_count) return;
  GdrCamera cam = *camera;
  uint pixel = params.path.first_pixel + g;
  int px = (int)(pixel % (uint)params.path.width), py = (int)(pixel / (uint)params.path.width);
  float4 u = rng_block(params.path.seed, pixel, params.path.sample, RNG_BLOCK_CAMERA);
  float2 jitter = sample_filter(cam.filter, cam.filter_radius, u.xy);
  float3 o, d;
  float tnear, tfar;
  camera_ray(&cam, px + 0.5f + jitter.x, py + 0.5f + jitter.y, &o, &d, &tnear, &tfar);
  write_ray_hit(&base_rays[g], o, d, tnear, tfar, g);
  GptBaseState b;
  b.throughput[0] = b.throughput[1] = b.throughput[2] = 1.0f;
  b.bsdf_pdf = 0.0f;
  b.pixel = pixel;
  b.sample = params.path.sample;
  b.depth = 0;
  b.flags = PATH_FLAG_SPECULAR;
  b.rr_prob = 1.0f;
  bases[g] = b;
  for (int j = 0; j < GPT_ACC_COUNT; ++j) acc[pixel * GPT_ACC_COUNT + j] = (float4)(0.0f);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    GptOffsetState os;
    os.throughput[0] = os.throughput[1] = os.throughput[2] = 1.0f;
    os.ratio = 1.0f;
    vstore3(o, 0, os.prev_pos);
    os.last_pdf = 1.0f;
    os.last_delta = 0;
    os.visible = 0;
    int nx = px + OFFSET_PIXEL_DX(k), ny = py + OFFSET_PIXEL_DY(k);
    if (nx < 0 || ny < 0 || nx >= params.path.width || ny >= params.path.height) {
      kill_offset(&os, counters, GPT_COUNTER_FAIL_OUTSIDE);
    } else {
      // The pixel shift: the same filter sample, one pixel over (Jacobian 1).
      float3 oo, od;
      float on, of;
      camera_ray(&cam, nx + 0.5f + jitter.x, ny + 0.5f + jitter.y, &oo, &od, &on, &of);
      os.mode = GPT_MODE_TRACE;
      vstore3(od, 0, os.dir);
      uint slot = atomic_inc(&counters[GPT_COUNTER_OFFSET_RAYS]);
      write_ray_hit(&offset_rays[slot], oo, od, on, of, g * GPT_OFFSETS + (uint)k);
    }
    offsets[g * GPT_OFFSETS + k] = os;
  }
}

// Files Embree's answers for the offsets: hits of their own rays, visibility of reconnections.
__kernel void gpt_scatter(uint ray_count, __global const GdrRayHit* offset_rays, uint reconnect_count,
                          __global const GdrRay* reconnect_rays, __global GptOffsetState* offsets) {
  uint i = get_global_id(0);
  if (i < ray_count) {
    GdrRayHit rh = offset_rays[i];
    __global GptOffsetState* o = &offsets[rh.ray.id];
    o->prim = rh.hit.geomID == GDR_INVALID_ID ? GDR_INVALID_ID : rh.hit.primID;
    o->b1 = rh.hit.u;
    o->b2 = rh.hit.v;
    o->t = rh.ray.tfar;
  } else if (i < ray_count + reconnect_count) {
    GdrRay r = reconnect_rays[i - ray_count];
    offsets[r.id].visible = r.tfar >= 0.0f;
  }
}
