// Gradient-domain path tracing (Kettunen et al. 2015) in a wavefront. A group per pixel sample:
// the base path and four offset paths through the neighbouring pixels. Per bounce:
//   gpt_shade  (base at x_k, offsets at their vertices): emission and next-event estimation for
//              all five paths with the pairwise MIS weights, then the base's BSDF sample;
//   host       Embree: the base's next ray, all shadow rays; gpt_shadow adds the unoccluded ones;
//   gpt_shift  (the base's next vertex x_{k+1} is known): each traced offset follows the base's
//              scattering at its own vertex by reconnection, half-vector copy, delta-lobe copy or
//              random-number replay;
//   host       Embree: offset rays, reconnection segments; gpt_scatter files the results.
// gpt_gather turns a pass's per-group sums into primal, gradient and direct-light images.
#include "bsdf/bsdf.h"
#include "camera/camera.h"
#include "core/ray_queue.h"
#include "core/rng.h"
#include "gpt/shift.h"
#include "light/lights.h"
#include "scene/surface.h"
#include "shared/gpt_types.h"
#include "shared/pt_types.h"

#define OFFSET_PIXEL_DX(k) ((k) == GPT_DIR_PX ? 1 : (k) == GPT_DIR_NX ? -1 : 0)
#define OFFSET_PIXEL_DY(k) ((k) == GPT_DIR_PY ? 1 : (k) == GPT_DIR_NY ? -1 : 0)

inline SceneData gpt_scene(const GdrGptParams* p, SCENE_DATA_ARGS) {
  return scene_data_make(SCENE_DATA_NAMES, p->path.light_count, p->path.env_light);
}

// Accumulators are indexed by pixel over the whole image, so gpt_gather can read neighbours.
inline void acc_add(__global float4* acc, uint pixel, int slot, float3 c) {
  if (c.x != 0.0f || c.y != 0.0f || c.z != 0.0f) acc[pixel * GPT_ACC_COUNT + slot] += (float4)(c, 0.0f);
}

inline void kill_offset(GptOffsetState* o, __global uint* counters, int reason) {
  o->mode = GPT_MODE_DEAD;
  atomic_inc(&counters[reason]);
}

inline int offset_alive(const GptOffsetState* o) { return o->mode != GPT_MODE_DEAD; }

// A contribution that is not finite is dropped and counted (never reaches a film).
inline float3 checked(float3 c, __global uint* counters) {
  if (is_finite3(c)) return c;
  atomic_inc(&counters[GPT_COUNTER_NONFINITE]);
  return (float3)(0.0f);
}

inline Bsdf surface_bsdf(const SceneData* s, const Surface* su) {
  return bsdf_from_material(&s->materials[su->material], surface_reflectance(s, su));
}

inline int is_diffuse(const Bsdf* b, float threshold) { return bsdf_roughness(b) > threshold; }

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

__kernel void gpt_shade(GdrGptParams params, uint count, __global const GdrRayHit* base_in,
                        __global GdrRayHit* base_out, __global GdrRay* shadow_rays, __global GptBaseState* bases,
                        __global GptOffsetState* offsets, __global float4* acc, __global float4* pend,
                        __global uint* counters, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  SceneData s = gpt_scene(&params, SCENE_DATA_NAMES);
  GdrRayHit rh = base_in[q];
  uint g = rh.ray.id;
  GptBaseState base = bases[g];
  GptOffsetState o[GPT_OFFSETS];
  for (int k = 0; k < GPT_OFFSETS; ++k) o[k] = offsets[g * GPT_OFFSETS + k];
  for (int j = 0; j < GPT_PEND_COUNT; ++j) pend[g * GPT_PEND_COUNT + j] = (float4)(0.0f);

  float3 dir = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  float3 beta = vload3(0, base.throughput);
  int base_hit = rh.hit.geomID != GDR_INVALID_ID;
  int direct = base.depth == 0;  // emission seen from the camera stays out of the gradients

  // Outcomes of the last shift step: where each offset got to.
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (o[k].mode == GPT_MODE_TRACE && (o[k].prim != GDR_INVALID_ID) != base_hit) {
      kill_offset(&o[k], counters, GPT_COUNTER_FAIL_ENVIRONMENT);
    } else if (o[k].mode == GPT_MODE_RECONNECTING) {
      if (o[k].visible) o[k].mode = GPT_MODE_JOINED_RECENT;
      else kill_offset(&o[k], counters, GPT_COUNTER_FAIL_OCCLUDED);
    }
  }

  float p_bsdf = base.bsdf_pdf;
  int last_specular = (base.flags & PATH_FLAG_SPECULAR) != 0;

  if (!base_hit) {
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    if (s.env_light >= 0) {
      __global const GdrLight* env = &s.lights[s.env_light];
      float3 le = environment_radiance(&s, env, dir);
      if (direct) {
        acc_add(acc, base.pixel, GPT_ACC_DIRECT, checked(beta * le, counters));
      } else {
        float p_light = last_specular ? 0.0f : environment_pdf(&s, dir);
        for (int k = 0; k < GPT_OFFSETS; ++k) {
          float w;
          float3 c_off = (float3)(0.0f);
          if (!offset_alive(&o[k])) {
            w = gpt_weight(p_bsdf, p_light, 0.0f, 0.0f, 0.0f);
          } else {
            // A traced offset escaped along its own direction; a joined one along the base's.
            float3 d_off = o[k].mode == GPT_MODE_TRACE ? vload3(0, o[k].dir) : dir;
            float p_off = o[k].last_pdf;
            float q_off = o[k].last_delta ? 0.0f : environment_pdf(&s, d_off);
            w = gpt_weight(p_bsdf, p_light, o[k].ratio * safe_div(p_bsdf, p_off), p_off, q_off);
            c_off = vload3(0, o[k].throughput) * environment_radiance(&s, env, d_off);
          }
          acc_add(acc, base.pixel, GPT_ACC_BASE(k), checked(w * beta * le, counters));
          acc_add(acc, base.pixel, GPT_ACC_OFFSET(k), checked(w * c_off, counters));
        }
      }
    }
#endif
    for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];
    return;
  }

  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  float3 wo = -dir;
  Surface so[GPT_OFFSETS];   // the offsets' current vertices
  float3 wo_off[GPT_OFFSETS];  // and their directions toward their previous vertices (world)
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    so[k] = su;
    wo_off[k] = wo;
    if (o[k].mode == GPT_MODE_TRACE) {
      so[k] = surface_at(&s, o[k].prim, o[k].b1, o[k].b2);
      wo_off[k] = -vload3(0, o[k].dir);
    } else if (o[k].mode == GPT_MODE_JOINED_RECENT) {
      wo_off[k] = normalize_or(vload3(0, o[k].prev_pos) - su.p, wo);
    }
  }

#if defined(GDR_LIGHT_AREA)
  // Emission found by BSDF sampling.
  if (su.light >= 0 || !direct) {
    float3 le = su.light >= 0 ? area_radiance(&s, su.light, su.ng, wo) : (float3)(0.0f);
    if (direct) {
      acc_add(acc, base.pixel, GPT_ACC_DIRECT, checked(beta * le, counters));
    } else {
      float p_light = (last_specular || su.light < 0) ? 0.0f : area_pdf(&s, su.light, su.area, rh.ray.tfar, dot(su.ng, wo));
      for (int k = 0; k < GPT_OFFSETS; ++k) {
        float w;
        float3 c_off = (float3)(0.0f);
        if (!offset_alive(&o[k])) {
          w = gpt_weight(p_bsdf, p_light, 0.0f, 0.0f, 0.0f);
        } else {
          float3 le_off = (float3)(0.0f);
          float q_off = 0.0f;
          if (so[k].light >= 0) {
            float dist = o[k].mode == GPT_MODE_TRACE          ? o[k].t
                         : o[k].mode == GPT_MODE_JOINED_RECENT ? length(vload3(0, o[k].prev_pos) - su.p)
                                                               : rh.ray.tfar;
            le_off = area_radiance(&s, so[k].light, so[k].ng, wo_off[k]);
            if (!o[k].last_delta) q_off = area_pdf(&s, so[k].light, so[k].area, dist, dot(so[k].ng, wo_off[k]));
          }
          float p_off = o[k].last_pdf;
          w = gpt_weight(p_bsdf, p_light, o[k].ratio * safe_div(p_bsdf, p_off), p_off, q_off);
          c_off = vload3(0, o[k].throughput) * le_off;
        }
        if (su.light >= 0 || c_off.x > 0.0f || c_off.y > 0.0f || c_off.z > 0.0f) {
          acc_add(acc, base.pixel, GPT_ACC_BASE(k), checked(w * beta * le, counters));
          acc_add(acc, base.pixel, GPT_ACC_OFFSET(k), checked(w * c_off, counters));
        }
      }
    }
  }
#endif

  if (params.path.max_depth > 0 && base.depth + 2 > params.path.max_depth) {
    for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];
    return;
  }

  Bsdf b = surface_bsdf(&s, &su);
  Frame frame = frame_from_normal(su.ns);
  float3 wo_l = frame_to_local(&frame, wo);

  // Next-event estimation: the base samples a light point; offsets reconnect to the same point.
  if (s.light_count > 0 && !bsdf_is_delta(&b)) {
    float4 ul = rng_block(params.path.seed, base.pixel, base.sample, RNG_BLOCK_LIGHT(base.depth));
    int light = light_select(&s, ul.x);
    LightSample ls;
    int usable = light_sample(&s, light, su.p, ul.yz, &ls);
    float3 wi_l = usable ? frame_to_local(&frame, ls.wi) : (float3)(0.0f);
    // A light sample the base cannot use (shading and geometric normals disagree) is no sample
    // at all, also for its offsets: the neighbour's base rejects the mirrored case the same way,
    // which keeps the pairwise weights summing to one.
    if (usable && dot(ls.wi, su.ng) * wi_l.z > 0.0f) {
      float3 f_le = bsdf_eval(&b, wo_l, wi_l) * ls.radiance / ls.pdf;  // per unit throughput
      float3 c_base = beta * f_le;
      float p_light = ls.pdf, p_b = ls.delta ? 0.0f : bsdf_pdf(&b, wo_l, wi_l);
      int base_ray_needed = 0;
      for (int k = 0; k < GPT_OFFSETS; ++k) {
        float w = gpt_weight(p_light, p_b, 0.0f, 0.0f, 0.0f);
        float3 c_off = (float3)(0.0f);
        int own_ray = 0;
        if (o[k].mode == GPT_MODE_JOINED) {
          w = gpt_weight(p_light, p_b, o[k].ratio, p_light, p_b);
          c_off = vload3(0, o[k].throughput) * f_le;
        } else if (o[k].mode == GPT_MODE_JOINED_RECENT) {
          float3 wr = frame_to_local(&frame, wo_off[k]);
          float q_b = ls.delta ? 0.0f : bsdf_pdf(&b, wr, wi_l);
          w = gpt_weight(p_light, p_b, o[k].ratio, p_light, q_b);
          c_off = vload3(0, o[k].throughput) * bsdf_eval(&b, wr, wi_l) * ls.radiance / ls.pdf;
        } else if (o[k].mode == GPT_MODE_TRACE) {
          Bsdf bo = surface_bsdf(&s, &so[k]);
          LightSample lo = ls;
          if (!bsdf_is_delta(&bo) && light_connect(&s, light, so[k].p, &lo)) {
            Frame fo = frame_from_normal(so[k].ns);
            float3 wol = frame_to_local(&fo, wo_off[k]), wil = frame_to_local(&fo, lo.wi);
            if (dot(lo.wi, so[k].ng) * wil.z > 0.0f) {
              float q_b = lo.delta ? 0.0f : bsdf_pdf(&bo, wol, wil);
              float jac = 1.0f;
              if (!lo.delta && !isinf(lo.dist)) jac = reconnect_jacobian(su.p, so[k].p, so[k].p + lo.wi * lo.dist, lo.light_normal);
              w = gpt_weight(p_light, p_b, o[k].ratio, p_light, jac * q_b);
              c_off = vload3(0, o[k].throughput) * bsdf_eval(&bo, wol, wil) * lo.radiance / lo.pdf;
              own_ray = c_off.x > 0.0f || c_off.y > 0.0f || c_off.z > 0.0f;
              if (own_ray) {
                c_off = checked(w * c_off, counters);
                pend[g * GPT_PEND_COUNT + GPT_PEND_OWN(k)] = (float4)(c_off, 0.0f);
                uint r = atomic_inc(&counters[GPT_COUNTER_SHADOW_RAYS]);
                write_light_ray(&shadow_rays[r], so[k].p, so[k].ng, lo.wi, lo.dist, GPT_SHADOW_ID(g, 1 + k));
              }
            }
          }
        }
        float3 cb = checked(w * c_base, counters);
        pend[g * GPT_PEND_COUNT + GPT_PEND_BASE(k)] = (float4)(cb, 0.0f);
        base_ray_needed |= cb.x > 0.0f || cb.y > 0.0f || cb.z > 0.0f;
        if (!own_ray && (o[k].mode == GPT_MODE_JOINED || o[k].mode == GPT_MODE_JOINED_RECENT)) {
          float3 co = checked(w * c_off, counters);
          pend[g * GPT_PEND_COUNT + GPT_PEND_JOINED(k)] = (float4)(co, 0.0f);
          base_ray_needed |= co.x > 0.0f || co.y > 0.0f || co.z > 0.0f;
        }
      }
      if (base_ray_needed) {
        uint r = atomic_inc(&counters[GPT_COUNTER_SHADOW_RAYS]);
        write_light_ray(&shadow_rays[r], su.p, su.ng, ls.wi, ls.dist, GPT_SHADOW_ID(g, 0));
      }
    }
  }

  // The base's BSDF sample; Russian roulette is decided by the base.
  float4 ub = rng_block(params.path.seed, base.pixel, base.sample, RNG_BLOCK_BSDF(base.depth));
  BsdfSample bs;
  int alive = bsdf_sample(&b, wo_l, ub.xyz, &bs);
  float3 wi = alive ? frame_to_world(&frame, bs.wi) : wo;
  alive = alive && dot(wi, su.ng) * bs.wi.z > 0.0f;
  if (alive) {
    beta *= bs.weight;
    alive = is_finite3(beta) && max3(beta) > 0.0f;
  }
  float rr = 1.0f;
  if (alive && base.depth + 1 >= params.path.rr_depth) {
    rr = fmin(max3(beta), 0.95f);
    alive = ub.w < rr;
  }
  if (!alive) {
    for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];
    return;
  }
  beta /= rr;

  // Offsets that share this vertex follow the base's sample directly.
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (o[k].mode != GPT_MODE_JOINED && o[k].mode != GPT_MODE_JOINED_RECENT) continue;
    float3 t = vload3(0, o[k].throughput);
    if (o[k].mode == GPT_MODE_JOINED) {
      t *= bs.weight;
      o[k].last_pdf = bs.pdf;
    } else {
      float3 wr = frame_to_local(&frame, wo_off[k]);
      float3 f = bsdf_eval(&b, wr, bs.wi);
      float p = bsdf_pdf(&b, wr, bs.wi);
      if (bs.delta || !(p > 0.0f) || max3(f) <= 0.0f) {
        kill_offset(&o[k], counters, GPT_COUNTER_FAIL_ZERO);
        continue;
      }
      t *= f / bs.pdf;
      o[k].ratio *= p / bs.pdf;
      o[k].last_pdf = p;
      o[k].mode = GPT_MODE_JOINED;
    }
    o[k].last_delta = bs.delta;
    if (rr < 1.0f) {
      // The offset's own-base Russian roulette would have used its own throughput.
      o[k].ratio *= fmin(max3(t / o[k].ratio), 0.95f) / rr;
      t /= rr;
    }
    if (!is_finite3(t) || !isfinite(o[k].ratio)) {
      kill_offset(&o[k], counters, GPT_COUNTER_FAIL_NONFINITE);
      continue;
    }
    vstore3(t, 0, o[k].throughput);
  }
  for (int k = 0; k < GPT_OFFSETS; ++k) offsets[g * GPT_OFFSETS + k] = o[k];

  base.depth += 1;
  base.bsdf_pdf = bs.pdf;
  base.flags = bs.delta ? PATH_FLAG_SPECULAR : 0;
  vstore3(beta, 0, base.throughput);
  base.prim = rh.hit.primID;
  base.b1 = rh.hit.u;
  base.b2 = rh.hit.v;
  base.sample_delta = bs.delta;
  base.sample_transmitted = bs.transmitted;
  base.sample_eta = bs.eta;
  vstore3(wi, 0, base.wi);
  vstore3(wo, 0, base.wo);
  base.rr_prob = rr;
  bases[g] = base;
  uint slot = atomic_inc(&counters[GPT_COUNTER_BASE_RAYS]);
  write_ray_hit(&base_out[slot], offset_ray_origin(su.p, dot(wi, su.ng) > 0.0f ? su.ng : -su.ng), wi, 0.0f, INFINITY, g);
}

// Adds the next-event contributions whose shadow rays Embree found unoccluded.
__kernel void gpt_shadow(uint count, __global const GdrRay* shadow_rays, __global const float4* pend,
                         __global const GptBaseState* bases, __global float4* acc) {
  uint i = get_global_id(0);
  if (i >= count) return;
  GdrRay r = shadow_rays[i];
  if (r.tfar < 0.0f) return;
  uint g = r.id / 8u, kind = r.id % 8u;
  uint pixel = bases[g].pixel;
  // The base's ray (kind 0) and offset k's own ray both add to ACC_OFFSET(k) without atomics:
  // safe because an offset is either joined (its share rides on the base's ray, PEND_JOINED) or
  // traced (its own ray, PEND_OWN), never both, and acc_add skips the zero entries.
  if (kind == 0u) {
    for (int k = 0; k < GPT_OFFSETS; ++k) {
      acc_add(acc, pixel, GPT_ACC_BASE(k), pend[g * GPT_PEND_COUNT + GPT_PEND_BASE(k)].xyz);
      acc_add(acc, pixel, GPT_ACC_OFFSET(k), pend[g * GPT_PEND_COUNT + GPT_PEND_JOINED(k)].xyz);
    }
  } else {
    int k = (int)kind - 1;
    acc_add(acc, pixel, GPT_ACC_OFFSET(k), pend[g * GPT_PEND_COUNT + GPT_PEND_OWN(k)].xyz);
  }
}

// The base's next vertex x_{k+1} is known: every traced offset shifts its outgoing direction.
__kernel void gpt_shift(GdrGptParams params, uint count, __global const GdrRayHit* base_rays,
                        __global GdrRayHit* offset_rays, __global GdrRay* reconnect_rays,
                        __global const GptBaseState* bases, __global GptOffsetState* offsets,
                        __global uint* counters, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  SceneData s = gpt_scene(&params, SCENE_DATA_NAMES);
  GdrRayHit rh = base_rays[q];
  uint g = rh.ray.id;
  GptBaseState base = bases[g];
  Surface sx = surface_at(&s, base.prim, base.b1, base.b2);
  Bsdf bx = surface_bsdf(&s, &sx);
  Frame fx = frame_from_normal(sx.ns);
  float3 wo_l = frame_to_local(&fx, vload3(0, base.wo));
  float3 wi_w = vload3(0, base.wi);
  float3 wi_l = frame_to_local(&fx, wi_w);
  float p_base = base.bsdf_pdf;
  int next_hit = rh.hit.geomID != GDR_INVALID_ID;
  float4 ub = rng_block(params.path.seed, base.pixel, base.sample, RNG_BLOCK_BSDF(base.depth - 1));
  float thr = params.shift_threshold;

  for (int k = 0; k < GPT_OFFSETS; ++k) {
    __global GptOffsetState* og = &offsets[g * GPT_OFFSETS + k];
    if (og->mode != GPT_MODE_TRACE) continue;
    GptOffsetState o = *og;
    Surface sy = surface_at(&s, o.prim, o.b1, o.b2);
    Bsdf by = surface_bsdf(&s, &sy);
    Frame fy = frame_from_normal(sy.ns);
    float3 woy = frame_to_local(&fy, -vload3(0, o.dir));
    float3 t = vload3(0, o.throughput);
    float3 wiy_w;  // the offset's new direction (world)
    int reconnect = 0;
    int reason = 0;

    if (params.shift == GPT_SHIFT_REPLAY) {
      BsdfSample so;
      if (!bsdf_sample(&by, woy, ub.xyz, &so) || so.delta != base.sample_delta) {
        reason = GPT_COUNTER_FAIL_LOBE;
      } else {
        // Same random numbers: the path-space Jacobian is p(x)/p(y), so f(y)|J|/p(x) = f/p of
        // the offset's own sample and the pdf ratio does not change.
        t *= so.weight;
        o.last_pdf = so.pdf;
        o.last_delta = so.delta;
        wiy_w = frame_to_world(&fy, so.wi);
        atomic_inc(&counters[GPT_COUNTER_SHIFT_REPLAY]);
      }
    } else if (base.sample_delta) {
      BsdfSample so;
      if (!bsdf_sample_delta_lobe(&by, woy, base.sample_transmitted, &so)) {
        reason = base.sample_transmitted ? GPT_COUNTER_FAIL_REFRACTION : GPT_COUNTER_FAIL_LOBE;
      } else {
        t *= so.weight * (so.pdf / p_base);
        o.ratio *= so.pdf / p_base;
        o.last_pdf = so.pdf;
        o.last_delta = 1;
        wiy_w = frame_to_world(&fy, so.wi);
        atomic_inc(&counters[GPT_COUNTER_SHIFT_DELTA]);
      }
    } else {
      int diffuse_pair = is_diffuse(&bx, thr) && is_diffuse(&by, thr);
      Surface sn;
      int diffuse_next = 0;
      if (next_hit && diffuse_pair) {
        sn = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
        Bsdf bn = surface_bsdf(&s, &sn);
        diffuse_next = is_diffuse(&bn, thr);
      }
      float3 wiy;
      float jac = 1.0f;
      int ok = 1;
      if (diffuse_pair && diffuse_next) {
        // Reconnect to the base's next vertex.
        float3 d = sn.p - sy.p;
        wiy_w = normalize_or(d, wi_w);
        wiy = frame_to_local(&fy, wiy_w);
        jac = reconnect_jacobian(sx.p, sy.p, sn.p, sn.ng);
        // Both paths must reach x_{k+1} from the same side of its surface.
        ok = jac > 0.0f && dot(sx.p - sn.p, sn.ng) * dot(sy.p - sn.p, sn.ng) > 0.0f;
        reconnect = 1;
        if (ok) atomic_inc(&counters[GPT_COUNTER_SHIFT_RECONNECT]);
      } else if (diffuse_pair && !next_hit) {
        // The base escaped: reconnect at infinity, i.e. copy the direction (Jacobian 1).
        wiy_w = wi_w;
        wiy = frame_to_local(&fy, wiy_w);
        atomic_inc(&counters[GPT_COUNTER_SHIFT_DIRECTION]);
      } else {
        ok = shift_half_vector(wo_l, wi_l, base.sample_transmitted, base.sample_eta, woy, by.eta.x, &wiy, &jac);
        if (ok) {
          wiy_w = frame_to_world(&fy, wiy);
          atomic_inc(&counters[GPT_COUNTER_SHIFT_HALF_VECTOR]);
        } else {
          reason = base.sample_transmitted ? GPT_COUNTER_FAIL_REFRACTION : GPT_COUNTER_FAIL_ZERO;
        }
      }
      if (ok) {
        float3 f = bsdf_eval(&by, woy, wiy);
        float p = bsdf_pdf(&by, woy, wiy);
        if (!(p > 0.0f) || max3(f) <= 0.0f) {
          reason = GPT_COUNTER_FAIL_ZERO;
        } else {
          t *= f * (jac / p_base);
          o.ratio *= p * jac / p_base;
          o.last_pdf = p;
          o.last_delta = 0;
        }
      } else if (!reason) {
        reason = GPT_COUNTER_FAIL_ZERO;
      }
    }
    if (!reason && !(dot(wiy_w, sy.ng) * dot(wiy_w, sy.ns) > 0.0f)) reason = GPT_COUNTER_FAIL_ZERO;
    if (!reason && base.rr_prob < 1.0f) {
      // The offset's own-base Russian roulette would have used its own throughput.
      o.ratio *= fmin(max3(t / o.ratio), 0.95f) / base.rr_prob;
      t /= base.rr_prob;
    }
    if (!reason && (!is_finite3(t) || !isfinite(o.ratio))) reason = GPT_COUNTER_FAIL_NONFINITE;
    if (reason) {
      kill_offset(&o, counters, reason);
      *og = o;
      continue;
    }
    vstore3(t, 0, o.throughput);
    vstore3(sy.p, 0, o.prev_pos);
    vstore3(wiy_w, 0, o.dir);
    uint id = g * GPT_OFFSETS + (uint)k;
    if (reconnect) {
      o.mode = GPT_MODE_RECONNECTING;
      o.visible = 0;
      Surface sn = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
      uint r = atomic_inc(&counters[GPT_COUNTER_RECONNECT_RAYS]);
      write_segment_ray(&reconnect_rays[r], sy.p, sy.ng, sn.p, id);
    } else {
      uint r = atomic_inc(&counters[GPT_COUNTER_OFFSET_RAYS]);
      write_ray_hit(&offset_rays[r], offset_ray_origin(sy.p, dot(wiy_w, sy.ng) > 0.0f ? sy.ng : -sy.ng), wiy_w, 0.0f,
                    INFINITY, id);
    }
    *og = o;
  }
}

// One pass's sums into the film: the primal (each pixel the mean of its four pairwise
// estimates), the forward-difference gradients, and directly seen emission.
__kernel void gpt_gather(int width, int height, __global const float4* acc, __global float4* primal,
                         __global float4* dx, __global float4* dy, __global float4* direct,
                         __global float4* primal_sq) {
  uint p = get_global_id(0);
  if (p >= (uint)(width * height)) return;
  int x = (int)(p % (uint)width), y = (int)(p / (uint)width);
  float3 pairs = (float3)(0.0f);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    pairs += acc[p * GPT_ACC_COUNT + GPT_ACC_BASE(k)].xyz;
    int nx = x + OFFSET_PIXEL_DX(k), ny = y + OFFSET_PIXEL_DY(k);
    if (nx >= 0 && ny >= 0 && nx < width && ny < height) {
      uint n = (uint)(ny * width + nx);
      int opposite = k ^ 1;  // PX <-> NX, PY <-> NY
      pairs += acc[n * GPT_ACC_COUNT + GPT_ACC_OFFSET(opposite)].xyz;
    }
  }
  float3 d = acc[p * GPT_ACC_COUNT + GPT_ACC_DIRECT].xyz;
  float3 value = 0.25f * pairs + d;
  float3 gx = (float3)(0.0f), gy = (float3)(0.0f);
  if (x + 1 < width) {
    uint n = p + 1u;
    gx = (acc[p * GPT_ACC_COUNT + GPT_ACC_OFFSET(GPT_DIR_PX)].xyz - acc[p * GPT_ACC_COUNT + GPT_ACC_BASE(GPT_DIR_PX)].xyz) +
         (acc[n * GPT_ACC_COUNT + GPT_ACC_BASE(GPT_DIR_NX)].xyz - acc[n * GPT_ACC_COUNT + GPT_ACC_OFFSET(GPT_DIR_NX)].xyz);
  }
  if (y + 1 < height) {
    uint n = p + (uint)width;
    gy = (acc[p * GPT_ACC_COUNT + GPT_ACC_OFFSET(GPT_DIR_PY)].xyz - acc[p * GPT_ACC_COUNT + GPT_ACC_BASE(GPT_DIR_PY)].xyz) +
         (acc[n * GPT_ACC_COUNT + GPT_ACC_BASE(GPT_DIR_NY)].xyz - acc[n * GPT_ACC_COUNT + GPT_ACC_OFFSET(GPT_DIR_NY)].xyz);
  }
  primal[p] += (float4)(value, 0.0f);
  dx[p] += (float4)(gx, 0.0f);
  dy[p] += (float4)(gy, 0.0f);
  direct[p] += (float4)(d, 0.0f);
  primal_sq[p] += (float4)(value * value, 0.0f);
}
