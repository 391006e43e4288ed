// Wavefront path tracer: generate camera rays, shade hits (emission, next-event estimation with
// MIS, BSDF sampling, Russian roulette), and add unoccluded shadow-ray contributions. The host
// intersects the queues with Embree between these kernels.
#include "path/aux.h"
#include "path/camera_sample.h"
#include "path/continuation.h"
#include "path/emission.h"
#include "path/film.h"
#include "path/nee.h"
#include "path/scene.h"
#include "path/shadow.h"
#include "path/spawn.h"
#include "shared/pt_types.h"
#include "shared/ray_types.h"

__kernel void pt_generate(__global const GdrCamera* camera, GdrPtParams params, __global GdrRayHit* rays,
                          __global uint* queue, __global GdrPathState* paths) {
  uint i = get_global_id(0);
  if (i >= params.pixel_count) return;
  GdrCamera cam = *camera;
  uint pixel = params.first_pixel + i;
  CameraRay r = pixel_camera_ray(&cam, params.seed, pixel, params.sample);
  write_camera_ray(&rays[i], &r, i);
  queue[i] = i;
  paths[i] = path_start(pixel, params.sample);
}

__kernel void pt_shade(GdrPtParams params, uint count, __global const GdrRayHit* rays_in,
                       __global const uint* queue_in, __global GdrRayHit* rays_out, __global uint* queue_out,
                       __global GdrRay* shadow_rays, __global float4* shadow_values,
                       __global GdrPathState* paths, __global float4* film, __global uint* counters,
                       SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count || path_no_segments(params.max_depth)) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  __global uint* nonfinite = &counters[PT_COUNTER_NONFINITE];
  uint slot = queue_in[q];
  GdrPathState st = paths[slot];
  GdrRayHit rh = rays_in[q];
  float3 dir = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  float3 beta = vload3(0, st.throughput);

  if (rh.hit.geomID == GDR_INVALID_ID) {
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    if (s.env_light >= 0) film_add(film, st.pixel, path_escaped_emission(&s, &st, beta, dir, params.strategy), nonfinite);
#endif
    return;
  }

  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  float3 wo = -dir;
#if defined(GDR_LIGHT_AREA)
  float3 le;
  if (path_surface_emission(&s, &st, beta, &su, wo, rh.ray.tfar, params.strategy, &le)) {
    film_add(film, st.pixel, le, nonfinite);
  }
#endif
  if (path_depth_reached(&st, params.max_depth)) return;

  Bsdf b = surface_bsdf(&s, &su);
  Frame frame = frame_from_normal(su.ns);
  float3 wo_local = frame_to_local(&frame, wo);
  PathSampler ps = path_state_sampler(&st, params.seed);

  // Next-event estimation.
  int light;
  LightSample ls;
  float3 wi_local;
  if (params.strategy != PT_STRATEGY_BSDF && nee_applies(&s, &b) &&
      nee_sample(&s, &ps, st.depth, &su, &frame, &light, &ls, &wi_local)) {
    float3 f = bsdf_eval(&b, wo_local, wi_local);
    float w = nee_weight(&ls, params.strategy, &b, wo_local, wi_local);
    float3 c = beta * f * ls.radiance * (w / ls.pdf);
    if (max3(c) > 0.0f && finite_or_count(c, nonfinite)) {
      uint k = atomic_inc(&counters[PT_COUNTER_SHADOW_RAYS]);
      write_light_ray(&shadow_rays[k], su.p, su.ng, ls.wi, ls.dist, st.pixel);
      shadow_values[k] = (float4)(c, 0.0f);
    }
  }

  // BSDF sampling continues the path.
  BsdfSample bs;
  float3 wi;
  float rr;
  int next = path_continue(&st, &ps, params.rr_depth, &b, &frame, su.ng, wo_local, &beta, &bs, &wi, &rr);
  if (next == PATH_ENDS_NONFINITE) atomic_inc(nonfinite);
  if (next != PATH_CONTINUES) return;

  path_advance(&st, beta, &bs);
  paths[slot] = st;
  uint k = atomic_inc(&counters[PT_COUNTER_NEXT_RAYS]);
  queue_out[k] = slot;
  spawn_ray(&rays_out[k], su.p, su.ng, wi, slot);
}
