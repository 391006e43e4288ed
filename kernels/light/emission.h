// Emission sampling: the first vertex of a light subpath (a point on a light and a direction
// leaving it) for every emitter type, with the pdfs of both, and the same pdfs evaluated for a
// given point and direction (what bidirectional MIS needs of a light vertex it did not sample).
// After pbrt-v4's Light::SampleLe / PDF_Le. Lights at infinity (directional, constant,
// environment) emit through the disc of the scene's bounding sphere facing their direction, so
// every ray that can reach the scene is drawn (the disc's pdf is 1 / (pi R^2)).
//
// Measures: pdf_pos is per unit area (1 for a delta position: point and spot lights), pdf_dir per
// unit solid angle (1 for a delta direction: directional lights); neither includes the light's
// selection probability, which light_emission_sample returns apart (pmf).
#pragma once
#include "core/warp.h"
#include "light/lights.h"

typedef struct EmissionSample {
  float3 p;          // point the light subpath starts at
  float3 n;          // area lights: the light's geometric normal there; 0 for the others
  float3 dir;        // unit direction the emitted light travels
  float3 le;         // area, constant, envmap: radiance; point, spot: intensity; directional:
                     // irradiance (the flux through a unit area perpendicular to dir)
  float pdf_pos, pdf_dir, pmf;
  int delta_pos;     // point and spot lights: p is the only position
  int delta_dir;     // directional lights: dir is the only direction
  int light;
} EmissionSample;

// Point uniform on the disc of radius r about c facing w (perpendicular to w).
inline float3 disc_point(float3 c, float3 w, float r, float2 u) {
  Frame f = frame_from_normal(w);
  float2 d = square_to_uniform_disk_concentric(u) * r;
  return c + f.s * d.x + f.t * d.y;
}

// Direction uniform in the cone of half-angle acos(cos_max) about w, and its pdf.
inline float3 sample_cone(float3 w, float cos_max, float2 u) {
  float cos_t = 1.0f - u.x * (1.0f - cos_max);
  float sin_t = safe_sqrt(1.0f - cos_t * cos_t), phi = 2.0f * M_PI_F * u.y;
  Frame f = frame_from_normal(w);
  return normalize(frame_to_world(&f, (float3)(sin_t * cos(phi), sin_t * sin(phi), cos_t)));
}
inline float cone_pdf(float cos_max) { return 1.0f / (2.0f * M_PI_F * (1.0f - cos_max)); }

inline float infinite_disc_pdf(__global const GdrLight* l) {
  float r = l->scene_radius;
  return r > 0.0f ? 1.0f / (M_PI_F * r * r) : 0.0f;
}

// Samples light `index`'s emission from four uniforms (u_pos: the position, u_dir: the
// direction; lights at infinity draw their direction from u_dir and the disc point from u_pos).
// Returns 0 where the light emits nothing there (zero radiance, degenerate triangle).
inline int light_emission_sample_index(const SceneData* s, int index, float2 u_pos, float2 u_dir, EmissionSample* e) {
  __global const GdrLight* l = &s->lights[index];
  e->light = index;
  e->pmf = light_pmf(s, index);
  e->n = (float3)(0.0f);
  e->delta_pos = 0;
  e->delta_dir = 0;
  switch (l->type) {
#if defined(GDR_LIGHT_AREA)
    case LIGHT_AREA: {
      float2 b = sample_triangle_barycentrics(u_pos);
      Surface su = surface_at(s, (uint)l->triangle, b.x, b.y);
      if (!(su.area > 0.0f)) return 0;
      Frame f = frame_from_normal(su.ng);
      float3 wl = square_to_cosine_hemisphere(u_dir);
      e->p = su.p;
      e->n = su.ng;
      e->dir = normalize(frame_to_world(&f, wl));
      e->le = area_radiance(s, index, su.ng, e->dir);
      e->pdf_pos = 1.0f / su.area;
      e->pdf_dir = square_to_cosine_hemisphere_pdf(wl);
      break;
    }
#endif
#if defined(GDR_LIGHT_POINT) || defined(GDR_LIGHT_SPOT)
    case LIGHT_POINT:
    case LIGHT_SPOT:
      e->p = vload3(0, l->position);
      e->delta_pos = 1;
      e->pdf_pos = 1.0f;
      if (l->type == LIGHT_SPOT) {
        e->dir = sample_cone(vload3(0, l->direction), l->cos_cutoff, u_dir);
        e->pdf_dir = cone_pdf(l->cos_cutoff);
        e->le = vload3(0, l->radiance) * spot_falloff(l, e->dir);
      } else {
        e->dir = sample_uniform_sphere(u_dir);
        e->pdf_dir = GDR_INV_4PI;
        e->le = vload3(0, l->radiance);
      }
      break;
#endif
#if defined(GDR_LIGHT_DIRECTIONAL)
    case LIGHT_DIRECTIONAL:
      e->dir = vload3(0, l->direction);
      e->p = disc_point(vload3(0, l->position) - e->dir * l->scene_radius, e->dir, l->scene_radius, u_pos);
      e->delta_dir = 1;
      e->pdf_dir = 1.0f;
      e->pdf_pos = infinite_disc_pdf(l);
      e->le = vload3(0, l->radiance);
      break;
#endif
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    case LIGHT_CONSTANT:
    case LIGHT_ENVMAP: {
      // w: the direction toward the environment the light arrives from; it travels along -w.
      float pdf_w;
      float3 w = environment_sample(s, index, u_dir, &e->le, &pdf_w);
      e->dir = -w;
      e->p = disc_point(vload3(0, l->position) + w * l->scene_radius, e->dir, l->scene_radius, u_pos);
      e->pdf_dir = e->pmf > 0.0f ? pdf_w / e->pmf : 0.0f;
      e->pdf_pos = infinite_disc_pdf(l);
      break;
    }
#endif
    default:
      return 0;
  }
  return e->pdf_pos > 0.0f && e->pdf_dir > 0.0f && isfinite(e->pdf_pos) && isfinite(e->pdf_dir) &&
         max3(e->le) > 0.0f && is_finite3(e->le);
}

// Picks a light by the selection cdf (u_select) and samples its emission.
inline int light_emission_sample(const SceneData* s, float u_select, float2 u_pos, float2 u_dir, EmissionSample* e) {
  if (s->light_count <= 0) return 0;
  return light_emission_sample_index(s, light_select(s, u_select), u_pos, u_dir, e);
}

// The throughput of the light subpath's first vertex: emission over the pdfs of the position,
// the direction and the light's selection, with the cosine at the light for area lights
// (pbrt-v4: Le |cos| / (pmf pdf_pos pdf_dir)).
inline float3 emission_throughput(const EmissionSample* e) {
  float c = e->delta_pos || dot(e->n, e->n) == 0.0f ? 1.0f : fabs(dot(e->n, e->dir));
  float p = e->pmf * e->pdf_pos * e->pdf_dir;
  return p > 0.0f ? e->le * (c / p) : (float3)(0.0f);
}

// The direction pdf light_emission_sample_index has of emitting along `dir` from light `index`
// (n: the light's normal at the point, for area lights); 0 for delta directions.
inline float light_emission_pdf_dir(const SceneData* s, int index, float3 n, float3 dir) {
  __global const GdrLight* l = &s->lights[index];
  switch (l->type) {
    case LIGHT_AREA: return fmax(dot(n, dir), 0.0f) * M_1_PI_F;
    case LIGHT_POINT: return GDR_INV_4PI;
    case LIGHT_SPOT: return dot(dir, vload3(0, l->direction)) > l->cos_cutoff ? cone_pdf(l->cos_cutoff) : 0.0f;
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    case LIGHT_CONSTANT:
    case LIGHT_ENVMAP: {
      float pmf = light_pmf(s, index);
      return pmf > 0.0f ? environment_pdf(s, -dir) / pmf : 0.0f;
    }
#endif
    default: return 0.0f;
  }
}

// The area pdf of the position, for a light point already known to lie on the light (its
// triangle's `area` for area lights); 1 for the delta positions of point and spot lights.
inline float light_emission_pdf_pos(const SceneData* s, int index, float area) {
  __global const GdrLight* l = &s->lights[index];
  switch (l->type) {
    case LIGHT_AREA: return area > 0.0f ? 1.0f / area : 0.0f;
    case LIGHT_POINT:
    case LIGHT_SPOT: return 1.0f;
    default: return infinite_disc_pdf(l);
  }
}

// Lights at infinity: a light subpath's first segment from them has no length.
inline int light_is_infinite(const SceneData* s, int index) {
  int type = s->lights[index].type;
  return type == LIGHT_DIRECTIONAL || type == LIGHT_CONSTANT || type == LIGHT_ENVMAP;
}

// Bidirectional MIS compares a light point's two ways of being drawn: by next-event estimation
// (the "direct" pdf: selection times position for lights at a finite distance, selection times
// direction for lights at infinity) and by emission sampling (selection, position and direction).
// Their ratio is the emission's other factor: the direction's pdf toward `dir` for finite lights
// (n: the area light's normal there), the disc's for lights at infinity.
inline float light_emission_over_direct(const SceneData* s, int index, float3 n, float3 dir) {
  if (light_is_infinite(s, index)) return infinite_disc_pdf(&s->lights[index]);
  return light_emission_pdf_dir(s, index, n, dir);
}

// The direct pdf (as above) of the light point an emission sample started from.
inline float emission_direct_pdf(const SceneData* s, const EmissionSample* e) {
  if (light_is_infinite(s, e->light)) return e->pmf * (e->delta_dir ? 1.0f : e->pdf_dir);
  return e->pmf * e->pdf_pos;
}
