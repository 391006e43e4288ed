// Wavefront path tracer: generate camera rays, shade hits (emission, next-event estimation with
// MIS, BSDF sampling, Russian roulette), and add unoccluded shadow-ray contributions. The host
// intersects the queues with Embree between these kernels.
#include "bsdf/bsdf.h"
#include "camera/camera.h"
#include "core/ray_queue.h"
#include "core/rng.h"
#include "light/lights.h"
#include "scene/surface.h"
#include "shared/pt_types.h"
#include "shared/ray_types.h"

// Adds a finite contribution to a pixel; a NaN or Inf one is counted and dropped.
inline void film_add(__global float4* film, uint pixel, float3 c, __global uint* counters) {
  if (!is_finite3(c)) {
    atomic_inc(&counters[PT_COUNTER_NONFINITE]);
    return;
  }
  film[pixel] += (float4)(c, 0.0f);
}

__kernel void pt_generate(__global const GdrCamera* camera, GdrPtParams params, __global GdrRayHit* rays,
                          __global uint* queue, __global GdrPathState* paths) {
  uint i = get_global_id(0);
  if (i >= params.pixel_count) return;
  GdrCamera cam = *camera;
  uint pixel = params.first_pixel + i;
  float4 u = rng_block(params.seed, pixel, params.sample, RNG_BLOCK_CAMERA);
  float2 offset = sample_filter(cam.filter, cam.filter_radius, u.xy);
  float fx = (float)(pixel % (uint)cam.width) + 0.5f + offset.x;
  float fy = (float)(pixel / (uint)cam.width) + 0.5f + offset.y;
  float3 o, d;
  float tnear, tfar;
  camera_ray(&cam, fx, fy, &o, &d, &tnear, &tfar);
  write_ray_hit(&rays[i], o, d, tnear, tfar, i);
  queue[i] = i;
  GdrPathState st;
  st.throughput[0] = st.throughput[1] = st.throughput[2] = 1.0f;
  st.bsdf_pdf = 0.0f;
  st.pixel = pixel;
  st.sample = params.sample;
  st.depth = 0;
  st.flags = PATH_FLAG_SPECULAR;  // emission seen from the camera is never MIS-weighted
  paths[i] = st;
}

// MIS weight of emission found by BSDF sampling, against light sampling with pdf `light_pdf`.
inline float emission_weight(const GdrPathState* st, int strategy, float light_pdf) {
  if (st->depth == 0 || (st->flags & PATH_FLAG_SPECULAR) || strategy == PT_STRATEGY_BSDF) return 1.0f;
  if (strategy == PT_STRATEGY_LIGHT) return 0.0f;
  return power_heuristic(st->bsdf_pdf, light_pdf);
}

__kernel void pt_shade(GdrPtParams params, uint count, __global const GdrRayHit* rays_in,
                       __global const uint* queue_in, __global GdrRayHit* rays_out, __global uint* queue_out,
                       __global GdrRay* shadow_rays, __global float4* shadow_values,
                       __global GdrPathState* paths, __global float4* film, __global uint* counters,
                       SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  SceneData s = scene_data_make(SCENE_DATA_NAMES, params.light_count, params.env_light);
  uint slot = queue_in[q];
  GdrPathState st = paths[slot];
  GdrRayHit rh = rays_in[q];
  float3 dir = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  float3 beta = vload3(0, st.throughput);

  if (rh.hit.geomID == GDR_INVALID_ID) {
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    if (s.env_light >= 0) {
      float3 le = environment_radiance(&s, &s.lights[s.env_light], dir);
      film_add(film, st.pixel, beta * le * emission_weight(&st, params.strategy, environment_pdf(&s, dir)), counters);
    }
#endif
    return;
  }

  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  float3 wo = -dir;
#if defined(GDR_LIGHT_AREA)
  if (su.light >= 0) {
    float3 le = area_radiance(&s, su.light, su.ng, wo);
    if (le.x > 0.0f || le.y > 0.0f || le.z > 0.0f) {
      float light_pdf = area_pdf(&s, su.light, su.area, rh.ray.tfar, dot(su.ng, wo));
      film_add(film, st.pixel, beta * le * emission_weight(&st, params.strategy, light_pdf), counters);
    }
  }
#endif
  // Mitsuba's max_depth counts segments: the next vertex would make depth + 2 of them.
  if (params.max_depth > 0 && st.depth + 2 > params.max_depth) return;

  Bsdf b = bsdf_from_material(&s.materials[su.material], surface_reflectance(&s, &su));
  Frame frame = frame_from_normal(su.ns);
  float3 wo_local = frame_to_local(&frame, wo);

  // Next-event estimation.
  if (params.strategy != PT_STRATEGY_BSDF && s.light_count > 0 && !bsdf_is_delta(&b)) {
    float4 ul = rng_block(params.seed, st.pixel, st.sample, RNG_BLOCK_LIGHT(st.depth));
    int light = light_select(&s, ul.x);
    LightSample ls;
    if (light_sample(&s, light, su.p, ul.yz, &ls)) {
      float3 wi_local = frame_to_local(&frame, ls.wi);
      // Shading and geometric normals must agree on the side of wi, or light leaks through.
      if (dot(ls.wi, su.ng) * wi_local.z > 0.0f) {
        float3 f = bsdf_eval(&b, wo_local, wi_local);
        float w = (ls.delta || params.strategy == PT_STRATEGY_LIGHT) ? 1.0f
                  : power_heuristic(ls.pdf, bsdf_pdf(&b, wo_local, wi_local));
        float3 c = beta * f * ls.radiance * (w / ls.pdf);
        if (max3(c) > 0.0f) {
          if (!is_finite3(c)) {
            atomic_inc(&counters[PT_COUNTER_NONFINITE]);
          } else {
            uint k = atomic_inc(&counters[PT_COUNTER_SHADOW_RAYS]);
            write_light_ray(&shadow_rays[k], su.p, su.ng, ls.wi, ls.dist, st.pixel);
            shadow_values[k] = (float4)(c, 0.0f);
          }
        }
      }
    }
  }

  // BSDF sampling continues the path.
  float4 ub = rng_block(params.seed, st.pixel, st.sample, RNG_BLOCK_BSDF(st.depth));
  BsdfSample bs;
  if (!bsdf_sample(&b, wo_local, ub.xyz, &bs)) return;
  float3 wi = frame_to_world(&frame, bs.wi);
  if (dot(wi, su.ng) * bs.wi.z <= 0.0f) return;
  beta *= bs.weight;
  if (!is_finite3(beta)) {
    atomic_inc(&counters[PT_COUNTER_NONFINITE]);
    return;
  }
  if (st.depth + 1 >= params.rr_depth) {
    float p = fmin(max3(beta), 0.95f);
    if (!(ub.w < p)) return;
    beta /= p;
  }
  if (max3(beta) <= 0.0f) return;

  st.depth += 1;
  st.bsdf_pdf = bs.pdf;
  st.flags = bs.delta ? PATH_FLAG_SPECULAR : 0;
  vstore3(beta, 0, st.throughput);
  paths[slot] = st;
  uint k = atomic_inc(&counters[PT_COUNTER_NEXT_RAYS]);
  queue_out[k] = slot;
  write_ray_hit(&rays_out[k], offset_ray_origin(su.p, dot(wi, su.ng) > 0.0f ? su.ng : -su.ng), wi, 0.0f, INFINITY, slot);
}

// Adds the contributions of the shadow rays Embree found unoccluded (blocked ones have tfar = -inf).
__kernel void pt_shadow(uint count, __global const GdrRay* shadow_rays, __global const float4* shadow_values,
                        __global float4* film) {
  uint k = get_global_id(0);
  if (k >= count) return;
  if (shadow_rays[k].tfar >= 0.0f) film[shadow_rays[k].id] += shadow_values[k];
}

// Auxiliary layers from the camera rays' first hits (for denoisers and inspection): albedo (the
// diffuse reflectance, or the specular scale of a material without one), shading normal and
// distance. Misses add zero.
__kernel void pt_aux(GdrPtParams params, uint count, __global const GdrRayHit* rays, __global float4* albedo,
                     __global float4* normal, __global float* depth, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count) return;
  GdrRayHit rh = rays[i];
  if (rh.hit.geomID == GDR_INVALID_ID) return;
  SceneData s = scene_data_make(SCENE_DATA_NAMES, params.light_count, params.env_light);
  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  Bsdf b = bsdf_from_material(&s.materials[su.material], surface_reflectance(&s, &su));
  float3 a = bsdf_has_diffuse_lobe(&b) ? b.diffuse : b.specular_r;
  uint pixel = params.first_pixel + rh.ray.id;
  albedo[pixel] += (float4)(a, 0.0f);
  normal[pixel] += (float4)(su.ns, 0.0f);
  depth[pixel] += rh.ray.tfar;
}
