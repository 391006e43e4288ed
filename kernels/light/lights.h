// Emitters: sampling a direction toward a light (next-event estimation), the emission a ray
// meets, and the solid-angle pdfs MIS needs. Compiled per scene: GDR_LIGHT_<TYPE> selects the
// emitter types present; with GDR_LIGHTS_SELECTED undefined (tests) all of them are compiled.
#pragma once
#include "core/geometry.h"
#include "scene/scene_data.h"
#include "scene/surface.h"
#include "light/envmap.h"

#if !defined(GDR_LIGHTS_SELECTED)
#define GDR_LIGHT_AREA 1
#define GDR_LIGHT_POINT 1
#define GDR_LIGHT_SPOT 1
#define GDR_LIGHT_DIRECTIONAL 1
#define GDR_LIGHT_CONSTANT 1
#define GDR_LIGHT_ENVMAP 1
#endif

typedef struct LightSample {
  float3 wi;        // unit direction from the shading point toward the light
  float dist;       // distance to the light point (INFINITY for directional and environment)
  float3 radiance;  // radiance arriving along -wi (intensity / d^2 for point lights)
  float pdf;        // solid-angle pdf including the light's selection probability; for delta
                    // lights the selection probability alone
  int delta;        // 1 for point, spot, directional
  float2 bary;      // area lights: the sampled point's barycentrics on the light's triangle
  float3 light_normal;  // area lights: the light's geometric normal at that point
} LightSample;

inline float light_pmf(const SceneData* s, int index) {
  return s->light_cdf[index + 1] - s->light_cdf[index];
}

// Picks a light in proportion to the cdf (binary search).
inline int light_select(const SceneData* s, float u) {
  int lo = 0, hi = s->light_count - 1;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (s->light_cdf[mid + 1] <= u) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

inline void copy_matrix(__global const float* m, float* out) {
  for (int i = 0; i < 12; ++i) out[i] = m[i];
}

#if defined(GDR_LIGHT_ENVMAP)
// World direction dir in the map's frame (unit).
inline float3 envmap_local_direction(__global const GdrLight* l, float3 dir) {
  float to_local[12];
  copy_matrix(l->to_local, to_local);
  return normalize(xform_vector(to_local, dir));
}

// Solid-angle pdf of local direction d of a map chosen with probability pmf, from its density
// p_uv per unit u and v there (envmap_uv_pdf). d(solid angle) = 2 pi^2 sin(theta) du dv. Written
// once for values of type F and directions of type D (float and float3 here, float8 and Lanes3 in
// light/envmap_lanes.h).
#define ENVMAP_SOLID_ANGLE(name, F, D)                                                                 \
  inline F name(float pmf, D d, F p_uv) {                                                              \
    F sin_theta = sqrt(d.x * d.x + d.z * d.z);                                                         \
    return select((F)(0.0f), pmf * p_uv / (2.0f * M_PI_F * M_PI_F * sin_theta), sin_theta > 0.0f);   \
  }
ENVMAP_SOLID_ANGLE(envmap_solid_angle, float, float3)

// Solid-angle pdf of sampling local direction d (at lat-long position uv) from the map of light
// l, chosen with probability pmf.
inline float envmap_solid_angle_pdf(const SceneData* s, __global const GdrLight* l, float pmf, float3 d, float2 uv) {
  __global const GdrTexture* t = &s->textures[l->texture];
  return envmap_solid_angle(pmf, d, envmap_uv_pdf(s, t, uv));
}
#endif

// Environment emission seen along world direction `dir`.
inline float3 environment_radiance(const SceneData* s, __global const GdrLight* l, float3 dir) {
#if defined(GDR_LIGHT_ENVMAP)
  if (l->type == LIGHT_ENVMAP) {
    float2 uv = envmap_uv(envmap_local_direction(l, dir));
    return envmap_lookup(s, &s->textures[l->texture], uv) * vload3(0, l->radiance);
  }
#endif
  return vload3(0, l->radiance);
}

// Solid-angle pdf of sampling world direction `dir` toward the environment, selection included.
inline float environment_pdf(const SceneData* s, float3 dir) {
  if (s->env_light < 0) return 0.0f;
  float pmf = light_pmf(s, s->env_light);
#if defined(GDR_LIGHT_ENVMAP)
  __global const GdrLight* l = &s->lights[s->env_light];
  if (l->type == LIGHT_ENVMAP) {
    float3 d = envmap_local_direction(l, dir);
    return envmap_solid_angle_pdf(s, l, pmf, d, envmap_uv(d));
  }
#endif
  return pmf * GDR_INV_4PI;
}

// Both of the above for the scene's environment (s->env_light >= 0), from one conversion of dir
// to the map's position: the radiance arriving along -dir, and *pdf.
inline float3 environment_eval(const SceneData* s, float3 dir, float* pdf) {
  __global const GdrLight* l = &s->lights[s->env_light];
  float pmf = light_pmf(s, s->env_light);
#if defined(GDR_LIGHT_ENVMAP)
  if (l->type == LIGHT_ENVMAP) {
    float3 d = envmap_local_direction(l, dir);
    float p_uv;
    float3 texel = envmap_lookup_pdf(s, &s->textures[l->texture], envmap_uv(d), &p_uv);
    *pdf = envmap_solid_angle(pmf, d, p_uv);
    return texel * vload3(0, l->radiance);
  }
#endif
  *pdf = pmf * GDR_INV_4PI;
  return vload3(0, l->radiance);
}

#if defined(GDR_LIGHT_ENVMAP)
// The direction toward envmap light l (chosen with probability pmf) at the lat-long position uv
// it drew, from what its texels hold there (envmap_lookup_pdf: texel, p_uv), with
// *radiance and *pdf as environment_eval gives them along it: read at uv rather than at the
// direction's position (which would convert it back).
inline float3 envmap_sample_at(__global const GdrLight* l, float pmf, float2 uv, float p_uv, float3 texel,
                               float3* radiance, float* pdf) {
  float3 d = envmap_direction(uv);
  *pdf = envmap_solid_angle(pmf, d, p_uv);
  *radiance = texel * vload3(0, l->radiance);
  float to_world[12];
  copy_matrix(l->to_world, to_world);
  return normalize(xform_vector(to_world, d));
}
#endif

// A direction toward environment light `index`: by the envmap's weights, or uniform for a
// constant one; *radiance and *pdf as environment_eval gives them along it.
inline float3 environment_sample(const SceneData* s, int index, float2 u, float3* radiance, float* pdf) {
  __global const GdrLight* l = &s->lights[index];
  float pmf = light_pmf(s, index);
#if defined(GDR_LIGHT_ENVMAP)
  if (l->type == LIGHT_ENVMAP) {
    __global const GdrTexture* t = &s->textures[l->texture];
    float2 uv = envmap_sample_uv(s, t, s->env_tables + l->distribution_offset, u);
    float p_uv;
    float3 texel = envmap_lookup_pdf(s, t, uv, &p_uv);
    return envmap_sample_at(l, pmf, uv, p_uv, texel, radiance, pdf);
  }
#endif
  *pdf = pmf * GDR_INV_4PI;
  *radiance = vload3(0, l->radiance);
  return sample_uniform_sphere(u);
}

// Emission of area light `index` toward `wo` (unit, pointing away from the surface with normal ng).
inline float3 area_radiance(const SceneData* s, int index, float3 ng, float3 wo) {
  return dot(ng, wo) > 0.0f ? vload3(0, s->lights[index].radiance) : (float3)(0.0f);
}

// Solid-angle pdf of a uniform point on a triangle of the given area, chosen with probability pmf,
// seen at distance dist under the light's cosine cos_light. Written once for values of type F
// (float here, float8 in light/light_lanes.h).
#define AREA_SOLID_ANGLE(name, F)                                                                         \
  inline F name(F pmf, F area, F dist, F cos_light) {                                                     \
    return select(pmf * dist * dist / (cos_light * area), (F)(0.0f), (cos_light <= 0.0f) | (area <= 0.0f)); \
  }
AREA_SOLID_ANGLE(area_solid_angle, float)

// Solid-angle pdf with which light sampling picks the point hit on triangle light `index`.
inline float area_pdf(const SceneData* s, int index, float area, float dist, float cos_light) {
  return area_solid_angle(light_pmf(s, index), area, dist, cos_light);
}

// Spot emission toward `dir` (unit, from the light) relative to its intensity: Mitsuba's falloff,
// linear in angle between the beam width and the cutoff; 0 outside the cone.
inline float spot_falloff(__global const GdrLight* l, float3 dir) {
  float cos_theta = dot(dir, vload3(0, l->direction));
  if (cos_theta <= l->cos_cutoff) return 0.0f;
  if (cos_theta >= l->cos_falloff) return 1.0f;
  float cutoff = acos(l->cos_cutoff), beam = acos(l->cos_falloff);
  float angle = acos(clamp(cos_theta, -1.0f, 1.0f));
  return cutoff > beam ? (cutoff - angle) / (cutoff - beam) : 0.0f;
}

// Evaluates the light point already chosen in ls (ls->bary for area lights; for lights at
// infinity ls->wi, and for an environment the radiance and pdf sampled with it) as seen from p:
// direction, distance, arriving radiance and pdf. Next-event estimation samples the point first;
// a gradient-domain offset path reconnects to the same point from its own vertex. Returns 0 when
// the light cannot contribute.
__attribute__((always_inline)) inline int light_connect(const SceneData* s, int index, float3 p, LightSample* ls) {
  __global const GdrLight* l = &s->lights[index];
  float pmf = light_pmf(s, index);
  ls->delta = 0;
  switch (l->type) {
#if defined(GDR_LIGHT_AREA)
    case LIGHT_AREA: {
      Surface su = surface_at(s, (uint)l->triangle, ls->bary.x, ls->bary.y);
      float3 d = su.p - p;
      float dist = length(d);
      if (!(dist > 0.0f)) return 0;
      ls->wi = d / dist;
      ls->dist = dist;
      ls->radiance = area_radiance(s, index, su.ng, -ls->wi);
      ls->pdf = area_pdf(s, index, su.area, dist, dot(su.ng, -ls->wi));
      ls->light_normal = su.ng;
      return ls->pdf > 0.0f && isfinite(ls->pdf);
    }
#endif
#if defined(GDR_LIGHT_POINT) || defined(GDR_LIGHT_SPOT)
    case LIGHT_POINT:
    case LIGHT_SPOT: {
      float3 d = vload3(0, l->position) - p;
      float dist2 = dot(d, d);
      if (!(dist2 > 0.0f)) return 0;
      float dist = sqrt(dist2);
      ls->wi = d / dist;
      ls->dist = dist;
      float falloff = 1.0f;
      if (l->type == LIGHT_SPOT) {
        if (dot(-ls->wi, vload3(0, l->direction)) <= l->cos_cutoff) return 0;
        falloff = spot_falloff(l, -ls->wi);
      }
      ls->radiance = vload3(0, l->radiance) * (falloff / dist2);
      ls->pdf = pmf;
      ls->delta = 1;
      return 1;
    }
#endif
#if defined(GDR_LIGHT_DIRECTIONAL)
    case LIGHT_DIRECTIONAL:
      ls->wi = -vload3(0, l->direction);
      ls->dist = INFINITY;
      ls->radiance = vload3(0, l->radiance);
      ls->pdf = pmf;
      ls->delta = 1;
      return 1;
#endif
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    case LIGHT_CONSTANT:
    case LIGHT_ENVMAP:
      // The same direction from any point: the sample's radiance and pdf hold as they are.
      ls->dist = INFINITY;
      return ls->pdf > 0.0f;
#endif
    default:
      return 0;
  }
}

// An environment light sample whose direction, radiance and pdf are set: the rest of it, and
// whether it is one.
inline int environment_sample_done(LightSample* ls) {
  ls->dist = INFINITY;
  ls->delta = 0;
  return ls->pdf > 0.0f;
}

// Samples a point on light `index` and evaluates it as seen from p.
__attribute__((always_inline)) inline int light_sample(const SceneData* s, int index, float3 p, float2 u,
                                                       LightSample* ls) {
  int type = s->lights[index].type;
  if (type == LIGHT_AREA) ls->bary = sample_triangle_barycentrics(u);
  if (type == LIGHT_CONSTANT || type == LIGHT_ENVMAP) {
    ls->wi = environment_sample(s, index, u, &ls->radiance, &ls->pdf);
    return environment_sample_done(ls);
  }
  return light_connect(s, index, p, ls);
}
