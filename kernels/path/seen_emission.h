// Emission seen directly by camera rays: one ray a pixel, and what its first hit emits toward the
// camera (area lights) or what its escape direction sees (the environment), added to a film slot.
// Light tracing's estimate of that emission, and the gradient-domain integrators' extra samples of
// their direct layer (render/seen_emission.h). A ray's pixel is params.first_pixel + its id.
#pragma once
#include "path/camera_sample.h"
#include "path/emission.h"
#include "path/film.h"
#include "path/scene.h"
#include "wavefront/counter_shard.h"

// The camera ray of `pixel` (its id), its filter offset from the camera's numbers of
// (seed, pixel, sample) (extra < 0) or extra sample `extra`'s (RNG_BLOCK_SEEN).
inline void seen_camera_ray(const GdrCamera* cam, const GdrPtParams* params, int extra, uint pixel, uint id,
                            __global GdrRayHit* ray) {
  PathSampler ps = path_sampler(params->seed, pixel, params->sample);
  CameraRay r = pixel_camera_ray_from(cam, pixel, sampler_block(&ps, extra < 0 ? RNG_BLOCK_CAMERA : RNG_BLOCK_SEEN(extra)));
  write_camera_ray(ray, &r, id);
}

// Camera rays of pixels [first_pixel, first_pixel + pixel_count), ray i's id i.
__kernel void seen_camera(__global const GdrCamera* camera, GdrPtParams params, int extra,
                          __global GdrRayHit* rays) {
  uint i = get_global_id(0);
  if (i >= params.pixel_count) return;
  GdrCamera cam = *camera;
  seen_camera_ray(&cam, &params, extra, params.first_pixel + i, i, &rays[i]);
}

// Camera rays of the listed pixels pixels[first, first + count), each ray's id its pixel.
__kernel void seen_camera_listed(__global const GdrCamera* camera, GdrPtParams params, int extra,
                                 __global const uint* pixels, uint first, uint count, __global GdrRayHit* rays) {
  uint i = get_global_id(0);
  if (i >= count) return;
  GdrCamera cam = *camera;
  uint pixel = pixels[first + i];
  seen_camera_ray(&cam, &params, extra, pixel, pixel, &rays[i]);
}

// Adds c to the film where finite (else counts it), with `hit_mark` in w where it is not zero.
inline void seen_add(__global float4* film, uint at, float3 c, float hit_mark, __global uint* nonfinite) {
  if (!finite_or_count(c, nonfinite)) return;
  int hit = c.x != 0.0f || c.y != 0.0f || c.z != 0.0f;
  film[at] += (float4)(c, hit ? hit_mark : 0.0f);
}

// The rays' emission into film[(params.first_pixel + id) * stride + slot], `hit_mark` added to its
// w where a ray sees some (SEEN_COUNTERS count what is dropped).
__kernel void seen_emission(GdrPtParams params, uint count, __global const GdrRayHit* rays, __global float4* film,
                            uint stride, uint slot, float hit_mark, __global uint* counters, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  __global uint* nonfinite = &counter_shard(counters)[SEEN_COUNTER_NONFINITE];
  GdrRayHit rh = rays[i];
  uint at = (params.first_pixel + rh.ray.id) * stride + slot;
  float3 dir = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  if (rh.hit.geomID == GDR_INVALID_ID) {
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    if (s.env_light >= 0) seen_add(film, at, escaped_radiance(&s, dir), hit_mark, nonfinite);
#endif
    return;
  }
#if defined(GDR_LIGHT_AREA)
  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  if (su.light >= 0) seen_add(film, at, surface_radiance(&s, &su, -dir), hit_mark, nonfinite);
#endif
}
