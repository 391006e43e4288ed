// G-PT: camera rays of the base and its four offsets (the pixel shift), and the filing of
// Embree's answers for the offsets. A group of pixel p (row-major) takes its film offset from the
// pixel's filter; a group of a Metropolis chain takes its film position from the chain's state,
// and its offsets lie one pixel away from it.
#pragma once
#include "gradient/accumulators.h"
#include "gradient/neighbours.h"
#include "gradient/offsets.h"
#include "camera/importance.h"
#include "gbidir/weights.h"
#include "path/camera_sample.h"
#include "path/path_state.h"
#include "path/shadow.h"
#include "wavefront/counter_shard.h"
#include "wavefront/group_reserve.h"

// Group g's base and offsets, up to the offsets' camera rays (traced[k], rays[k]; *count of them).
__attribute__((always_inline)) inline void gpt_generate_group(__global const GdrCamera* camera, GdrGptParams params,
                                                              uint g, __global GdrRayHit* base_rays,
                                                              __global GptBaseState* bases,
                                                              __global GptOffsetState* offsets,
                                                              __global GptChain* chains, __global float4* acc,
                                                              __global uint* stats, CameraRay* rays, int* traced,
                                                              uint* count, PRIMARY_SAMPLE_ARGS) {
  GdrCamera cam = *camera;
  uint pixel = params.path.first_pixel + g;
  PathSampler ps = path_sampler_bound(params.path.seed, pixel, params.path.sample, PRIMARY_SAMPLE_NAMES);
  int primary = sampler_is_primary(&ps);
  // Under chains: the film position's pixel and its offset from the pixel's centre.
  float2 raster = primary ? camera_primary_raster(&cam, &ps) : (float2)(0.0f);
  int px = primary ? (int)floor(raster.x) : (int)(pixel % (uint)params.path.width);
  int py = primary ? (int)floor(raster.y) : (int)(pixel / (uint)params.path.width);
  float2 jitter = primary ? raster - (float2)(px + 0.5f, py + 0.5f) : camera_jitter(&cam, &ps, px, py);
  CameraRay r = camera_sample(&cam, px, py, jitter);
  write_camera_ray(&base_rays[g], &r, g);
  GptBaseState b;
  b.path = path_start(pixel, params.path.sample);
  b.rr_prob = 1.0f;
#if defined(GDR_GBDPT)
  b.mis = gbdpt_sums_start(&cam, camera_cos_theta(&cam, r.d));
#endif
  bases[g] = b;
#if defined(GDR_MANIFOLD)
  chains[g].open = 0;
#endif
  for (int j = 0; j < GPT_ACC_COUNT; ++j) acc[pixel * GPT_ACC_COUNT + j] = (float4)(0.0f);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    GptOffsetState os;
    os.throughput[0] = os.throughput[1] = os.throughput[2] = 1.0f;
    os.ratio = 1.0f;
#if defined(GDR_GBDPT)
    os.mis = b.mis;  // its own from its camera ray below
#endif
    vstore3(r.o, 0, os.prev_pos);
    os.last_pdf = 1.0f;
    os.last_delta = 0;
    os.visible = 0;
    os.glossy_next_only = 0;  // the pixel shift holds wherever the offset lands
    int nx = px + OFFSET_PIXEL_DX(k), ny = py + OFFSET_PIXEL_DY(k);
    // The pixel shift keeps the film offset: its Jacobian is 1, and the two pixels' film
    // densities differ only near the image's edges, where the filter is cut (camera_shift_ratio).
    // A chain's offset is a film position like its base's: it must lie where camera samples do.
    float q = 0.0f;
    if (primary) {
      q = camera_raster_inside(&cam, raster + (float2)(OFFSET_PIXEL_DX(k), OFFSET_PIXEL_DY(k))) ? 1.0f : 0.0f;
    } else if (nx >= 0 && ny >= 0 && nx < params.path.width && ny < params.path.height) {
      q = camera_shift_ratio(&cam, px, py, nx, ny, jitter);
    }
    if (!(q > 0.0f) || !isfinite(q)) {
      // The neighbour is outside the image, or its film sample could not be here.
      kill_offset(&os, stats, GPT_COUNTER_FAIL_OUTSIDE);
    } else {
      CameraRay ro = camera_sample(&cam, nx, ny, jitter);
      os.mode = GPT_MODE_TRACE;
      os.throughput[0] = os.throughput[1] = os.throughput[2] = q;
      os.ratio = q;
      vstore3(ro.d, 0, os.dir);
#if defined(GDR_GBDPT)
      os.mis = gbdpt_sums_start(&cam, camera_cos_theta(&cam, ro.d));
#endif
      rays[k] = ro;
      traced[k] = 1;
      ++*count;
    }
    offsets[g * GPT_OFFSETS + k] = os;
  }
}

// The groups' camera rays; each work-group appends its offsets' rays together (group_reserve).
__kernel void gpt_generate(__global const GdrCamera* camera, GdrGptParams params, __global GdrRayHit* base_rays,
                           __global GdrRayHit* offset_rays, __global GptBaseState* bases,
                           __global GptOffsetState* offsets, __global GptChain* chains, __global float4* acc,
                           __global uint* counters, PRIMARY_SAMPLE_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint g = get_global_id(0);
  CameraRay rays[GPT_OFFSETS];
  int traced[GPT_OFFSETS];
  uint count = 0u;
  for (int k = 0; k < GPT_OFFSETS; ++k) traced[k] = 0;
  if (g < params.path.pixel_count) {
    gpt_generate_group(camera, params, g, base_rays, bases, offsets, chains, acc, counter_shard(counters), rays, traced,
                       &count, PRIMARY_SAMPLE_NAMES);
  }
  const uint which[1] = {GPT_COUNTER_OFFSET_RAYS};
  uint slot = count;
  group_reserve(scratch, counters, which, 1, &slot);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (traced[k]) write_camera_ray(&offset_rays[slot++], &rays[k], g * GPT_OFFSETS + (uint)k);
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
    offsets[r.id].visible = shadow_unoccluded(r.tfar);
  }
}
