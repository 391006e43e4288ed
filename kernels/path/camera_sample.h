// The camera sample of a pixel: an offset drawn from the pixel filter with the camera's random
// numbers, and the camera ray through the offset position. G-PT traces its four neighbours with
// the same offset (the pixel shift, Jacobian 1).
#pragma once
#include "camera/camera.h"
#include "core/ray_queue.h"
#include "sampling/path_sampler.h"

typedef struct CameraRay {
  float3 o, d;
  float tnear, tfar;
} CameraRay;

// Offset from the pixel centre (in pixels).
inline float2 camera_jitter(const GdrCamera* cam, const PathSampler* ps) {
  float4 u = sampler_block(ps, RNG_BLOCK_CAMERA);
  return sample_filter(cam->filter, cam->filter_radius, u.xy);
}

// The ray through pixel (x, y) at offset `jitter` from its centre.
inline CameraRay camera_sample(const GdrCamera* cam, int x, int y, float2 jitter) {
  CameraRay r;
  camera_ray(cam, x + 0.5f + jitter.x, y + 0.5f + jitter.y, &r.o, &r.d, &r.tnear, &r.tfar);
  return r;
}

inline void write_camera_ray(__global GdrRayHit* r, const CameraRay* c, uint id) {
  write_ray_hit(r, c->o, c->d, c->tnear, c->tfar, id);
}
