// Light samples and environment lookups for kernels that shade several lanes (pt/shade_lanes.h,
// pt/route_lanes.h): light_sample lane by lane, except that the lanes that chose an area light,
// and those that chose an environment map (light/envmap_lanes.h, as it looks up the lanes'
// escaped rays), are sampled together on lanes.
#pragma once
#include "core/lanes.h"
#include "light/envmap_lanes.h"
#include "light/lights.h"

// The light samples of eight lanes in the lane steps' layout. A lane without one (ok 0) holds
// harmless values: wi (0, 0, 1), no radiance, pdf 1.
typedef struct {
  LaneArray3 wi, radiance;
  float pdf[LANES], dist[LANES];
  int delta[LANES], ok[LANES];  // ok: -1 where the lane holds a sample
} LightSampleLanes;

inline void light_sample_lanes_set(LightSampleLanes* out, int k, const LightSample* ls) {
  lane_array3_set(&out->wi, k, ls->wi);
  lane_array3_set(&out->radiance, k, ls->radiance);
  out->pdf[k] = ls->pdf;
  out->dist[k] = ls->dist;
  out->delta[k] = ls->delta;
  out->ok[k] = -1;
}

// Non-delta samples drawn on lanes, into the lanes `on`.
inline void light_sample_lanes_merge(LightSampleLanes* out, int8 on, Lanes3 wi, Lanes3 radiance, float8 pdf,
                                     float8 dist) {
  lanes3_store(lanes3_select(lanes3_load(&out->wi), wi, on), &out->wi);
  lanes3_store(lanes3_select(lanes3_load(&out->radiance), radiance, on), &out->radiance);
  vstore8(select(vload8(0, out->pdf), pdf, on), 0, out->pdf);
  vstore8(select(vload8(0, out->dist), dist, on), 0, out->dist);
  vstore8(vload8(0, out->ok) | on, 0, out->ok);
}

#if defined(GDR_LIGHT_AREA)
AREA_SOLID_ANGLE(area_solid_angle_lanes, float8)

// light_sample for the lanes `on`, whose lights (light[k]) are area lights: each triangle's
// vertices (and shading normals) are read lane by lane; the point drawn by (u1, u2), surface_at's
// normals (the geometric one turned to the shading one's side) and area, and light_connect's
// direction, radiance and pdf seen from p, on lanes.
inline void area_light_sample_lanes(const SceneData* s, int8 on, const int* light, float8 u1, float8 u2, Lanes3 p,
                                    LightSampleLanes* out) {
  LaneArray3 v0, v1, v2, n0, n1, n2, le;
  float pmf[LANES];
  int normals[LANES], flip[LANES], on_k[LANES];
  vstore8(on, 0, on_k);
  for (int k = 0; k < LANES; ++k) {
    // Off lanes: a unit triangle, for harmless arithmetic.
    float3 a = (float3)(0.0f), b = (float3)(1.0f, 0.0f, 0.0f), c = (float3)(0.0f, 1.0f, 0.0f);
    float3 na = (float3)(0.0f), nb = (float3)(0.0f), nc = (float3)(0.0f), radiance = (float3)(0.0f);
    pmf[k] = 0.0f;
    normals[k] = flip[k] = 0;
    if (on_k[k]) {
      __global const GdrLight* l = &s->lights[light[k]];
      GdrTriangle tri = s->triangles[l->triangle];
      int flags = s->shapes[tri.shape].flags;
      a = s->positions[tri.v[0]].xyz;
      b = s->positions[tri.v[1]].xyz;
      c = s->positions[tri.v[2]].xyz;
      if (flags & SHAPE_HAS_NORMALS) {
        na = s->normals[tri.v[0]].xyz;
        nb = s->normals[tri.v[1]].xyz;
        nc = s->normals[tri.v[2]].xyz;
        normals[k] = -1;
      }
      flip[k] = flags & SHAPE_FLIP_NORMALS ? -1 : 0;
      radiance = vload3(0, l->radiance);
      pmf[k] = light_pmf(s, light[k]);
    }
    lane_array3_set(&v0, k, a);
    lane_array3_set(&v1, k, b);
    lane_array3_set(&v2, k, c);
    lane_array3_set(&n0, k, na);
    lane_array3_set(&n1, k, nb);
    lane_array3_set(&n2, k, nc);
    lane_array3_set(&le, k, radiance);
  }
  // sample_triangle_barycentrics, then surface_at.
  float8 su = sqrt(u1);
  float8 b1 = su * (1.0f - u2), b2 = su * u2, b0 = 1.0f - b1 - b2;
  Lanes3 P0 = lanes3_load(&v0), P1 = lanes3_load(&v1), P2 = lanes3_load(&v2);
  // One expression a component, as surface_at's: the compiler contracts both alike.
  Lanes3 point = {b0 * P0.x + b1 * P1.x + b2 * P2.x, b0 * P0.y + b1 * P1.y + b2 * P2.y,
                  b0 * P0.z + b1 * P1.z + b2 * P2.z};
  Lanes3 cr = lanes3_cross(lanes3_sub(P1, P0), lanes3_sub(P2, P0));
  float8 len = sqrt(lanes3_dot(cr, cr));
  float8 area = 0.5f * len;
  int8 has_len = len > 0.0f;
  Lanes3 ng = {select((float8)(0.0f), cr.x / len, has_len), select((float8)(0.0f), cr.y / len, has_len),
               select((float8)(1.0f), cr.z / len, has_len)};
  Lanes3 N0 = lanes3_load(&n0), N1 = lanes3_load(&n1), N2 = lanes3_load(&n2);
  Lanes3 n = {b0 * N0.x + b1 * N1.x + b2 * N2.x, b0 * N0.y + b1 * N1.y + b2 * N2.y, b0 * N0.z + b1 * N1.z + b2 * N2.z};
  float8 nl = sqrt(lanes3_dot(n, n));
  int8 use_n = (vload8(0, normals) != 0) & (nl > 0.0f) & isfinite(nl);
  Lanes3 n_unit = {n.x / nl, n.y / nl, n.z / nl};
  Lanes3 ns = lanes3_select(ng, n_unit, use_n);
  ns = lanes3_scale(ns, select((float8)(1.0f), (float8)(-1.0f), vload8(0, flip) != 0));
  ng = lanes3_scale(ng, select((float8)(1.0f), (float8)(-1.0f), lanes3_dot(ng, ns) < 0.0f));
  // light_connect's area case.
  Lanes3 d = lanes3_sub(point, p);
  float8 dist = sqrt(lanes3_dot(d, d));
  Lanes3 wi = {d.x / dist, d.y / dist, d.z / dist};
  float8 cos_light = -lanes3_dot(ng, wi);
  Lanes3 radiance = lanes3_scale(lanes3_load(&le), select((float8)(0.0f), (float8)(1.0f), cos_light > 0.0f));
  float8 pdf = area_solid_angle_lanes(vload8(0, pmf), area, dist, cos_light);
  light_sample_lanes_merge(out, on & (dist > 0.0f) & (pdf > 0.0f) & isfinite(pdf), wi, radiance, pdf, dist);
}
#endif

// light_sample for each lane k with want[k]: the light chosen by u0, a point on it by (u1, u2),
// seen from p.
inline void light_sample_lanes(const SceneData* s, const int* want, float8 u0, float8 u1, float8 u2,
                               const LaneArray3* p, LightSampleLanes* out) {
  Lanes3 up = {(float8)(0.0f), (float8)(0.0f), (float8)(1.0f)}, none = {(float8)(0.0f), (float8)(0.0f), (float8)(0.0f)};
  lanes3_store(up, &out->wi);
  lanes3_store(none, &out->radiance);
  vstore8((float8)(1.0f), 0, out->pdf);
  vstore8((float8)(0.0f), 0, out->dist);
  vstore8((int8)(0), 0, out->delta);
  vstore8((int8)(0), 0, out->ok);
  float u0_k[LANES], u1_k[LANES], u2_k[LANES];
  vstore8(u0, 0, u0_k);
  vstore8(u1, 0, u1_k);
  vstore8(u2, 0, u2_k);
  int env[LANES], area[LANES], light_of[LANES];
  for (int k = 0; k < LANES; ++k) {
    env[k] = area[k] = light_of[k] = 0;
    if (!want[k]) continue;
    int light = light_select(s, u0_k[k]);
    int type = s->lights[light].type;
#if defined(GDR_LIGHT_ENVMAP)
    if (type == LIGHT_ENVMAP) {
      env[k] = -1;  // drawn below
      continue;
    }
#endif
#if defined(GDR_LIGHT_AREA)
    if (type == LIGHT_AREA) {
      area[k] = -1;  // drawn below
      light_of[k] = light;
      continue;
    }
#endif
    LightSample ls;
    if (light_sample(s, light, lane_array3_get(p, k), (float2)(u1_k[k], u2_k[k]), &ls)) {
      light_sample_lanes_set(out, k, &ls);
    }
  }
#if defined(GDR_LIGHT_AREA)
  int8 on_area = vload8(0, area) != 0;
  if (any(on_area)) area_light_sample_lanes(s, on_area, light_of, u1, u2, lanes3_load(p), out);
#endif
#if defined(GDR_LIGHT_ENVMAP)
  int8 on = vload8(0, env) != 0;
  if (!any(on)) return;
  __global const GdrLight* l = &s->lights[s->env_light];
  __global const GdrTexture* t = &s->textures[l->texture];
  __global const float* table = s->env_tables + l->distribution_offset;
  float pmf = light_pmf(s, s->env_light);
  float8 u, v, p_uv;
  Lanes3 texel, radiance, wi;
  envmap_sample_uv_lanes(s, t, table, on, u1, u2, &u, &v);
  envmap_lookup_pdf_lanes(s, t, on, u, v, &texel, &p_uv);
  float8 pdf;
  wi = envmap_sample_at_lanes(l, pmf, u, v, p_uv, texel, &radiance, &pdf);
  // environment_sample_done: at infinity, not delta; a sample where its pdf is positive.
  light_sample_lanes_merge(out, on & (pdf > 0.0f), wi, radiance, pdf, (float8)(INFINITY));
#endif
}

#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
// environment_eval for each lane in `on` (the scene has an environment): the radiance arriving
// along -dir and *pdf.
inline Lanes3 environment_eval_lanes(const SceneData* s, int8 on, Lanes3 dir, float8* pdf) {
  __global const GdrLight* l = &s->lights[s->env_light];
  float pmf = light_pmf(s, s->env_light);
#if defined(GDR_LIGHT_ENVMAP)
  if (l->type == LIGHT_ENVMAP) return envmap_eval_lanes(s, l, pmf, on, dir, pdf);
#endif
  *pdf = (float8)(pmf * GDR_INV_4PI);
  float3 r = vload3(0, l->radiance);
  Lanes3 le = {(float8)(r.x), (float8)(r.y), (float8)(r.z)};
  return le;
}
#endif
