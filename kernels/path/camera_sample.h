// The camera sample of a pixel: an offset drawn from the pixel filter (cut to the image unless
// the film samples its border) with the camera's random numbers, and the camera ray through the
// offset position. G-PT traces its four neighbours with the same offset (the pixel shift).
#pragma once
#include "camera/camera.h"
#include "core/ray_queue.h"
#include "sampling/path_sampler.h"

typedef struct CameraRay {
  float3 o, d;
  float tnear, tfar;
} CameraRay;

// Offset from the centre of pixel (x, y) (in pixels), drawn from the pixel filter with u.xy.
inline float2 camera_filter_offset(const GdrCamera* cam, float4 u, int x, int y) {
  float2 rx = filter_range(cam, x, cam->width), ry = filter_range(cam, y, cam->height);
  return (float2)(sample_filter_axis(cam->filter, cam->filter_radius, rx, u.x),
                  sample_filter_axis(cam->filter, cam->filter_radius, ry, u.y));
}

// Offset from the centre of pixel (x, y) (in pixels), from the camera's random numbers.
inline float2 camera_jitter(const GdrCamera* cam, const PathSampler* ps, int x, int y) {
  return camera_filter_offset(cam, sampler_block(ps, RNG_BLOCK_CAMERA), x, y);
}

// The pixel shift: pixel (nx, ny) reuses the offset `jitter` of pixel (x, y). Returns the ratio
// of the two pixels' film densities there, q_n / q_p (the filter cancels, leaving the ratio of
// the filter masses over the two pixels' ranges; 1 away from the image's edges), or 0 where
// the offset lies outside the neighbour's range, which its own samples never reach.
inline float camera_shift_ratio(const GdrCamera* cam, int x, int y, int nx, int ny, float2 jitter) {
  float2 bx = filter_range(cam, x, cam->width), by = filter_range(cam, y, cam->height);
  float2 ox = filter_range(cam, nx, cam->width), oy = filter_range(cam, ny, cam->height);
  if (jitter.x < ox.x || jitter.x > ox.y || jitter.y < oy.x || jitter.y > oy.y) return 0.0f;
  // Away from the edges the two ranges are the same: the ratio is 1 without the filter's cdf.
  if (bx.x == ox.x && bx.y == ox.y && by.x == oy.x && by.y == oy.y) return 1.0f;
  int f = cam->filter;
  float r = cam->filter_radius;
  return (filter_mass(f, r, bx) / filter_mass(f, r, ox)) * (filter_mass(f, r, by) / filter_mass(f, r, oy));
}

// The ray through pixel (x, y) at offset `jitter` from its centre.
inline CameraRay camera_sample(const GdrCamera* cam, int x, int y, float2 jitter) {
  CameraRay r;
  camera_ray(cam, x + 0.5f + jitter.x, y + 0.5f + jitter.y, &r.o, &r.d, &r.tnear, &r.tfar);
  return r;
}

// The film positions a camera sample may take (camera_raster_inside): lower corner and size.
inline float4 camera_sample_region(const GdrCamera* cam) {
  float r = cam->sample_border ? cam->filter_radius : 0.0f;
  return (float4)(-r, -r, (float)cam->width + 2.0f * r, (float)cam->height + 2.0f * r);
}

// The region's area in pixels: what turns a radiance at a film position drawn uniformly over it
// into its share of the image's integral over primary sample space.
inline float camera_sample_area(const GdrCamera* cam) {
  float4 region = camera_sample_region(cam);
  return region.z * region.w;
}

// A film position drawn uniformly over the region from the camera block: a Metropolis chain's
// sample is not tied to a pixel, and its contribution is splatted where it lands.
inline float2 camera_primary_raster(const GdrCamera* cam, const PathSampler* ps) {
  float4 u = sampler_block(ps, RNG_BLOCK_CAMERA), region = camera_sample_region(cam);
  return region.xy + u.xy * region.zw;
}

// The ray through `pixel` (row-major) at its filter offset drawn with u.xy.
inline CameraRay pixel_camera_ray_from(const GdrCamera* cam, uint pixel, float4 u) {
  int px = (int)(pixel % (uint)cam->width), py = (int)(pixel / (uint)cam->width);
  return camera_sample(cam, px, py, camera_filter_offset(cam, u, px, py));
}

// The camera ray of the path of `ps`: with primary-sample-space numbers through its own film
// position, else through `pixel` (row-major) at its filter offset from the camera's numbers.
inline CameraRay sampler_camera_ray(const GdrCamera* cam, const PathSampler* ps, uint pixel) {
  if (sampler_is_primary(ps)) {
    float2 raster = camera_primary_raster(cam, ps);
    CameraRay r;
    camera_ray(cam, raster.x, raster.y, &r.o, &r.d, &r.tnear, &r.tfar);
    return r;
  }
  return pixel_camera_ray_from(cam, pixel, sampler_block(ps, RNG_BLOCK_CAMERA));
}

// The camera ray of sample `sample` of `pixel` (row-major): its filter offset from the camera's
// random numbers, then the ray through it.
inline CameraRay pixel_camera_ray(const GdrCamera* cam, uint seed, uint pixel, uint sample) {
  PathSampler ps = path_sampler(seed, pixel, sample);
  return sampler_camera_ray(cam, &ps, pixel);
}

inline void write_camera_ray(__global GdrRayHit* r, const CameraRay* c, uint id) {
  write_ray_hit(r, c->o, c->d, c->tnear, c->tfar, id);
}
