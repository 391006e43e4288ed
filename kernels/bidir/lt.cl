// Light tracer: light subpaths start at the lights (emission sampling), scatter by importance
// transport, and every vertex on a non-delta surface is connected to the camera and splatted;
// emission the camera sees directly comes from one camera ray per pixel (a light subpath cannot
// reach the pinhole by itself). The host intersects the queues with Embree between the kernels
// and gathers the splats after each bounce.
//
// Path lengths follow Mitsuba's max_depth (segments): a vertex k bounces from the light makes a
// path of k + 1 segments once connected to the camera; emission seen directly is one segment.
#include "camera/importance.h"
#include "light/emission.h"
#include "path/aux.h"
#include "path/camera_sample.h"
#include "path/continuation.h"
#include "path/emission.h"
#include "path/film.h"
#include "path/scene.h"
#include "path/shadow.h"
#include "path/spawn.h"
#include "path/splat.h"
#include "shared/lt_types.h"
#include "shared/ray_types.h"

// Mitsuba's max_depth allows `segments` path segments (< 0: unbounded).
inline int lt_segments_allowed(int max_depth, int segments) { return max_depth < 0 || segments <= max_depth; }

// Camera rays of pixels [first_pixel, first_pixel + pixel_count), for the emission seen directly.
__kernel void lt_camera(__global const GdrCamera* camera, GdrPtParams params, __global GdrRayHit* rays) {
  uint i = get_global_id(0);
  if (i >= params.pixel_count) return;
  GdrCamera cam = *camera;
  CameraRay r = pixel_camera_ray(&cam, params.seed, params.first_pixel + i, params.sample);
  write_camera_ray(&rays[i], &r, i);
}

// Adds what the camera rays' first hits emit toward the camera (area lights) or what their
// escape direction sees (the environment).
__kernel void lt_direct(GdrPtParams params, uint count, __global const GdrRayHit* rays, __global float4* film,
                        __global uint* counters, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count || !lt_segments_allowed(params.max_depth, 1)) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  __global uint* nonfinite = &counters[LT_COUNTER_NONFINITE];
  GdrRayHit rh = rays[i];
  uint pixel = params.first_pixel + rh.ray.id;
  float3 dir = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  if (rh.hit.geomID == GDR_INVALID_ID) {
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    if (s.env_light >= 0) film_add(film, pixel, escaped_radiance(&s, dir), nonfinite);
#endif
    return;
  }
#if defined(GDR_LIGHT_AREA)
  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  if (su.light >= 0) film_add(film, pixel, surface_radiance(&s, &su, -dir), nonfinite);
#endif
}

// Light subpaths [first_pixel, first_pixel + pixel_count) of the pass leave their lights: the
// emission sample, the first throughput, and the ray into queue 0 (compacted).
__kernel void lt_emit(GdrPtParams params, __global GdrRayHit* rays, __global uint* queue,
                      __global GdrLightPathState* paths, __global uint* counters, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= params.pixel_count) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  uint index = params.first_pixel + i;
  PathSampler ps = path_sampler(params.seed, index, params.sample);
  float4 ue = sampler_block(&ps, RNG_BLOCK_EMISSION), ud = sampler_block(&ps, RNG_BLOCK_EMISSION_DIR);
  EmissionSample e;
  if (!light_emission_sample(&s, ue.x, ue.yz, ud.xy, &e)) return;
  float3 beta = emission_throughput(&e);
  if (!finite_or_count(beta, &counters[LT_COUNTER_NONFINITE]) || !(max3(beta) > 0.0f)) return;
  atomic_inc(&counters[LT_COUNTER_SUBPATHS]);
  GdrLightPathState st;
  vstore3(beta, 0, st.throughput);
  st.rr_scale = max3(beta);
  st.index = index;
  st.sample = params.sample;
  st.depth = 0;
  st.pad0 = 0;
  paths[i] = st;
  uint k = atomic_inc(&counters[LT_COUNTER_NEXT_RAYS]);
  queue[k] = i;
  // Area lights: off the emitting surface; the other lights' points lie on no surface.
  float3 o = dot(e.n, e.n) > 0.0f ? leaving_origin(e.p, e.n, e.dir) : e.p;
  write_ray_hit(&rays[k], o, e.dir, 0.0f, INFINITY, i);
}

// A light subpath's new vertex: its connection to the camera (a splat in the path's slot and a
// shadow ray toward the camera) and its continuation by importance transport.
__kernel void lt_shade(GdrPtParams params, uint count, __global const GdrCamera* camera,
                       __global const GdrRayHit* rays_in, __global const uint* queue_in, __global GdrRayHit* rays_out,
                       __global uint* queue_out, __global GdrRay* shadow_rays, __global GdrSplat* splats,
                       __global GdrLightPathState* paths, __global uint* counters, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  GdrRayHit rh = rays_in[q];
  if (rh.hit.geomID == GDR_INVALID_ID) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  __global uint* nonfinite = &counters[LT_COUNTER_NONFINITE];
  uint slot = queue_in[q];
  GdrLightPathState st = paths[slot];
  float3 beta = vload3(0, st.throughput);
  int k = st.depth + 1;  // this vertex's bounces from the light
  float3 wo = -(float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  Bsdf b = surface_bsdf(&s, &su);
  Frame frame = frame_from_normal(su.ns);
  float3 wo_local = frame_to_local(&frame, wo);

  // Where the shading normal puts the light-side direction on the other side of the surface, the
  // path ends, as a camera path's sample toward the light does (path/sides.h): lt and pt accept
  // the same paths. The camera-side direction is left to the BSDF, as a camera ray's is.
  if (!sides_agree(wo, su.ng, wo_local.z)) return;

  // Connection to the camera: beta f (cos / d^2) cos_theta We, spread by the pixels' filters.
  GdrCamera cam = *camera;
  CameraProjection pr;
  if (lt_segments_allowed(params.max_depth, k + 1) && !bsdf_is_delta(&b) && camera_project(&cam, su.p, &pr)) {
    float3 wc = -pr.dir, wc_local = frame_to_local(&frame, wc);
    float3 f = bsdf_eval_transport(&b, wo_local, wc_local, TRANSPORT_IMPORTANCE) *
               shading_normal_correction(wo, wc, su.ng, wo_local.z, wc_local.z);
    float3 c = beta * f * (pr.cos_theta * camera_we(&cam, pr.cos_theta) / (pr.dist * pr.dist));
    if (max3(c) > 0.0f && finite_or_count(c, nonfinite)) {
      splat_write(&splats[slot], pr.raster, c);
      uint r = atomic_inc(&counters[LT_COUNTER_SHADOW_RAYS]);
      write_segment_ray(&shadow_rays[r], su.p, su.ng, camera_position(&cam), slot);
    }
  }

  // Continuation: the next vertex would make k + 2 segments once connected.
  if (!lt_segments_allowed(params.max_depth, k + 2)) return;
  PathSampler ps = path_sampler(params.seed, st.index, st.sample);
  BsdfSample bs;
  float3 wi;
  float rr;
  int next = path_continue_transport(st.depth, &ps, RNG_BLOCK_SUBPATH_BSDF(st.depth), params.rr_depth, st.rr_scale,
                                     TRANSPORT_IMPORTANCE, &b, &frame, su.ng, wo_local, &beta, &bs, &wi, &rr);
  if (next == PATH_ENDS_NONFINITE) atomic_inc(nonfinite);
  if (next != PATH_CONTINUES) return;
  st.depth = k;
  vstore3(beta, 0, st.throughput);
  paths[slot] = st;
  uint n = atomic_inc(&counters[LT_COUNTER_NEXT_RAYS]);
  queue_out[n] = slot;
  spawn_ray(&rays_out[n], su.p, su.ng, wi, slot);
}

// Empties the splat slots whose shadow ray toward the camera Embree found blocked.
__kernel void lt_shadow(uint count, __global const GdrRay* shadow_rays, __global GdrSplat* splats) {
  uint k = get_global_id(0);
  if (k >= count) return;
  if (!shadow_unoccluded(shadow_rays[k].tfar)) splat_drop(&splats[shadow_rays[k].id]);
}
