// Wavefront path tracer: generate camera rays, route hits to per-material queues, shade each
// queue (emission, next-event estimation with MIS, BSDF sampling, Russian roulette), and add
// unoccluded shadow-ray contributions. The host intersects the queues with Embree between these
// kernels.
#include "path/aux.h"
#include "path/camera_sample.h"
#include "path/continuation.h"
#include "path/emission.h"
#include "path/film.h"
#include "path/material_queues.h"
#include "path/nee.h"
#include "path/scene.h"
#include "path/shadow.h"
#include "path/spawn.h"
#include "shared/pt_types.h"
#include "shared/ray_types.h"
#include "wavefront/group_reserve.h"

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

// What a miss sees of the environment.
inline void pt_escaped(const GdrPtParams* params, const SceneData* s, const GdrRayHit* rh,
                       __global const GdrPathState* path, __global float4* film, __global uint* counters) {
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
  if (s->env_light < 0 || path_no_segments(params->max_depth)) return;
  GdrPathState st = *path;
  float3 dir = (float3)(rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z);
  film_add(film, st.pixel, path_escaped_emission(s, &st, vload3(0, st.throughput), dir, params->strategy),
           &counters[PT_COUNTER_NONFINITE]);
#endif
}

// Routes the queue's hits to the material queues (keys: each entry's BSDF type, from which
// render/wavefront/material_queues.h makes the queues) and adds what the misses see. Scenes with
// one material type skip it: their kernel takes the queue as it is, misses included.
__kernel void pt_route(GdrPtParams params, uint count, __global const GdrRayHit* rays_in,
                       __global const uint* queue_in, __global uint* keys, __global const GdrPathState* paths,
                       __global float4* film, __global uint* counters, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrRayHit rh = rays_in[q];
  if (rh.hit.geomID != GDR_INVALID_ID) {
    keys[q] = material_queue_key(&s, rh.hit.primID);
    return;
  }
  keys[q] = MATERIAL_QUEUE_NONE;
  pt_escaped(&params, &s, &rh, &paths[queue_in[q]], film, counters);
}

// A queue entry (hit rh of the path st, kept at `path`): a miss adds what it sees where the queue
// was not routed (`direct`) and gives 0; a hit gives its surface *su and adds what it emits
// toward the path.
__attribute__((always_inline)) inline int pt_entry_hit(const GdrPtParams* params, const SceneData* s, int direct,
                                                       const GdrRayHit* rh, __global const GdrPathState* path,
                                                       const GdrPathState* st, __global float4* film,
                                                       __global uint* counters, Surface* su) {
  if (rh->hit.geomID == GDR_INVALID_ID) {
    if (direct) pt_escaped(params, s, rh, path, film, counters);
    return 0;
  }
  *su = surface_at(s, rh->hit.primID, rh->hit.u, rh->hit.v);
#if defined(GDR_LIGHT_AREA)
  float3 le, wo = -(float3)(rh->ray.dir_x, rh->ray.dir_y, rh->ray.dir_z);
  if (path_surface_emission(s, st, vload3(0, st->throughput), su, wo, rh->ray.tfar, params->strategy, &le)) {
    film_add(film, st->pixel, le, &counters[PT_COUNTER_NONFINITE]);
  }
#endif
  return 1;
}

// A hit of a material of BSDF type `type`: emission, next-event estimation with MIS, then the
// BSDF sample that continues the path (Russian roulette). `direct`: the queue was not routed, and
// a miss is added here. Always inlined: called from one kernel per material, PoCL would otherwise
// keep the call (and shade about 9% slower).
// What a shaded hit appends to the queues: a shadow ray toward its light sample, the ray that
// continues its path.
typedef struct {
  float3 p, ng;                       // the hit
  float3 light_wi, shadow_value;      // the shadow ray's direction and what it adds if unblocked
  float light_dist;
  float3 wi;                          // the continuing ray's direction
  uint pixel, slot;
  int shadow, next;
} PtAppend;

__attribute__((always_inline)) inline void pt_shade_hit(GdrPtParams params, uint q, int type, int direct,
                                                        __global const GdrRayHit* rays_in,
                                                        __global const uint* queue_in, __global GdrPathState* paths,
                                                        __global float4* film, __global uint* counters,
                                                        const SceneData* sd, PtAppend* out) {
  if (path_no_segments(params.max_depth)) return;
  SceneData s = *sd;
  __global uint* nonfinite = &counters[PT_COUNTER_NONFINITE];
  uint slot = queue_in[q];
  GdrPathState st = paths[slot];
  GdrRayHit rh = rays_in[q];
  Surface su;
  if (!pt_entry_hit(&params, &s, direct, &rh, &paths[slot], &st, film, counters, &su)) return;
  float3 beta = vload3(0, st.throughput);
  float3 wo = -(float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  out->p = su.p;
  out->ng = su.ng;
  out->pixel = st.pixel;
  out->slot = slot;
  if (path_depth_reached(&st, params.max_depth)) return;

  Bsdf b = surface_bsdf_of_type(&s, &su, type);
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
      out->shadow = 1;
      out->light_wi = ls.wi;
      out->light_dist = ls.dist;
      out->shadow_value = c;
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
  out->next = 1;
  out->wi = wi;
}

// The arguments of a material queue's shading kernel (pt_shade_<material>, pt_shade_lanes_<material>).
#define PT_SHADE_ARGS                                                                                          \
  GdrPtParams params, uint count, uint first, int direct, __global const uint* sorted,                         \
      __global const GdrRayHit* rays_in, __global const uint* queue_in, __global GdrRayHit* rays_out,          \
      __global uint* queue_out, __global GdrRay* shadow_rays, __global float4* shadow_values,                  \
      __global GdrPathState* paths, __global float4* film, __global uint* counters, SCENE_DATA_ARGS

// pt_shade_<material>: the queue entries sorted[first, first + count) of one material (or, with
// `direct`, the queue's entries [0, count) themselves: the scene has one material type). The
// group appends its shadow and continuing rays together (group_reserve).
#define PT_SHADE_QUEUE(name, TYPE)                                                                            \
  __kernel void pt_shade_##name(PT_SHADE_ARGS) {                                                             \
    __local uint scratch[GROUP_RESERVE_SCRATCH];                                                             \
    uint i = get_global_id(0);                                                                               \
    PtAppend o;                                                                                              \
    o.shadow = o.next = 0;                                                                                   \
    if (i < count) {                                                                                         \
      SceneData s = path_scene(&params, SCENE_DATA_NAMES);                                                   \
      pt_shade_hit(params, direct ? i : sorted[first + i], TYPE, direct, rays_in, queue_in, paths, film,      \
                   counters, &s, &o);                                                                        \
    }                                                                                                        \
    const uint which[2] = {PT_COUNTER_SHADOW_RAYS, PT_COUNTER_NEXT_RAYS};                                    \
    uint k[2] = {(uint)o.shadow, (uint)o.next};                                                              \
    group_reserve(scratch, counters, which, 2, k);                                                           \
    if (o.shadow) {                                                                                          \
      write_light_ray(&shadow_rays[k[0]], o.p, o.ng, o.light_wi, o.light_dist, o.pixel);                     \
      shadow_values[k[0]] = (float4)(o.shadow_value, 0.0f);                                                  \
    }                                                                                                        \
    if (o.next) {                                                                                            \
      queue_out[k[1]] = o.slot;                                                                              \
      spawn_ray(&rays_out[k[1]], o.p, o.ng, o.wi, o.slot);                                                   \
    }                                                                                                        \
  }
GDR_MATERIAL_QUEUES(PT_SHADE_QUEUE)

#include "pt/generate_lanes.h"
#include "pt/route_lanes.h"
#include "pt/shade_lanes.h"
