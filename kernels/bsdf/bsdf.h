// The BSDF interface of the engine: one switch over the material types, each family in its own
// header (diffuse.h, conductor.h, dielectric.h, plastic.h; shared physics in fresnel.h and
// microfacet.h). Semantics follow Mitsuba 3's plugins of the same names.
//
// Conventions. Directions are in the local shading frame (z = shading normal), wo points toward
// the previous vertex (camera side), wi toward the next one; inputs are renormalized. Radiance
// transport: a refracted sample's weight and the BTDF include the 1 / eta^2 radiance scaling
// (multiply by s.eta^2 for importance transport). Opaque types (diffuse, conductors, plastics)
// are zero unless wo.z > 0 and wi.z > 0; with `twosided` both are first flipped to the upper
// side when wo.z < 0. Dielectrics are two-sided by nature (wo.z < 0: inside, eta inverted).
//
// Compile-time selection. With no GDR_BSDF_SELECTED defined (tests, tools) every type is
// compiled. A scene build defines GDR_BSDF_SELECTED plus one GDR_BSDF_<TYPE> per type it uses:
//   GDR_BSDF_DIFFUSE, GDR_BSDF_CONDUCTOR, GDR_BSDF_ROUGH_CONDUCTOR, GDR_BSDF_DIELECTRIC,
//   GDR_BSDF_THIN_DIELECTRIC, GDR_BSDF_ROUGH_DIELECTRIC, GDR_BSDF_PLASTIC, GDR_BSDF_ROUGH_PLASTIC
// A type left out evaluates to zero and never samples.
#pragma once
#include "bsdf/bsdf_types.h"
#include "bsdf/conductor.h"
#include "bsdf/dielectric.h"
#include "bsdf/diffuse.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "bsdf/plastic.h"
#include "core/frame.h"
#include "core/math.h"
#include "shared/material_class.h"
#include "shared/scene_types.h"

#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_DIFFUSE)
#define GDR_USE_DIFFUSE 1
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_CONDUCTOR)
#define GDR_USE_CONDUCTOR 1
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_ROUGH_CONDUCTOR)
#define GDR_USE_ROUGH_CONDUCTOR 1
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_DIELECTRIC)
#define GDR_USE_DIELECTRIC 1
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_THIN_DIELECTRIC)
#define GDR_USE_THIN_DIELECTRIC 1
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_ROUGH_DIELECTRIC)
#define GDR_USE_ROUGH_DIELECTRIC 1
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_PLASTIC)
#define GDR_USE_PLASTIC 1
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_ROUGH_PLASTIC)
#define GDR_USE_ROUGH_PLASTIC 1
#endif

// Resolves a material at a hit point; `reflectance` is the (textured) diffuse reflectance,
// `coating_tables` the scene's buffer of them (0 while they are being built).
inline Bsdf bsdf_from_material(__global const GdrMaterial* m, __global const float* coating_tables,
                               float3 reflectance) {
  Bsdf b;
  b.type = m->type;
  b.twosided = m->twosided;
  b.distribution = m->distribution == MICROFACET_BECKMANN ? MICROFACET_BECKMANN : MICROFACET_GGX;
  b.nonlinear = m->nonlinear;
  b.diffuse = reflectance;
  b.specular_r = vload3(0, m->specular_reflectance);
  b.specular_t = vload3(0, m->specular_transmittance);
  b.eta = vload3(0, m->eta);
  b.k = vload3(0, m->k);
  b.alpha_u = fmax(m->alpha_u, GDR_MIN_ALPHA);  // fmax also maps NaN to the minimum
  b.alpha_v = fmax(m->alpha_v, GDR_MIN_ALPHA);
  int is_interface = b.type == BSDF_DIELECTRIC || b.type == BSDF_THIN_DIELECTRIC ||
                  b.type == BSDF_ROUGH_DIELECTRIC || b.type == BSDF_PLASTIC ||
                  b.type == BSDF_ROUGH_PLASTIC;
  if (is_interface && !(b.eta.x > 0.0f && isfinite(b.eta.x))) b.eta.x = 1.0f;
  float s_mean = mean3(b.specular_r), d_mean = mean3(b.diffuse);
  b.specular_weight = s_mean + d_mean > 0.0f ? s_mean / (s_mean + d_mean) : 0.5f;
  b.coating = coating_tables && m->coating_table >= 0 ? coating_tables + m->coating_table : 0;
  b.internal_reflectance = coating_internal_reflectance(b.coating);
  return b;
}

// Opaque types shade only their upper side (or both, flipped, when two-sided).
inline int bsdf_is_opaque(const Bsdf* b) {
  return b->type == BSDF_DIFFUSE || b->type == BSDF_CONDUCTOR ||
         b->type == BSDF_ROUGH_CONDUCTOR || b->type == BSDF_PLASTIC ||
         b->type == BSDF_ROUGH_PLASTIC;
}

inline int bsdf_flip_side(const Bsdf* b, float3 wo) {
  return b->twosided && wo.z < 0.0f && bsdf_is_opaque(b);
}

// f(wo, wi) |cos wi| of the non-delta components (0 for pure delta BSDFs).
__attribute__((always_inline)) inline float3 bsdf_eval(const Bsdf* b, float3 wo, float3 wi) {
  wo = normalize_or(wo, (float3)(0.0f));
  wi = normalize_or(wi, (float3)(0.0f));
  if (bsdf_flip_side(b, wo)) {
    wo.z = -wo.z;
    wi.z = -wi.z;
  }
  float3 f = (float3)(0.0f);
  switch (b->type) {
#ifdef GDR_USE_DIFFUSE
    case BSDF_DIFFUSE: f = diffuse_eval(b, wo, wi); break;
#endif
#ifdef GDR_USE_ROUGH_CONDUCTOR
    case BSDF_ROUGH_CONDUCTOR: f = rough_conductor_eval(b, wo, wi); break;
#endif
#ifdef GDR_USE_ROUGH_DIELECTRIC
    case BSDF_ROUGH_DIELECTRIC: f = rough_dielectric_eval(b, wo, wi); break;
#endif
#ifdef GDR_USE_PLASTIC
    case BSDF_PLASTIC: f = plastic_eval(b, wo, wi); break;
#endif
#ifdef GDR_USE_ROUGH_PLASTIC
    case BSDF_ROUGH_PLASTIC: f = rough_plastic_eval(b, wo, wi); break;
#endif
    default: break;  // delta-only types and types not compiled in
  }
  return fmax(finite_or_zero3(f), (float3)(0.0f));
}

// Solid-angle pdf with which bsdf_sample produces wi through its non-delta components,
// lobe-selection probability included.
__attribute__((always_inline)) inline float bsdf_pdf(const Bsdf* b, float3 wo, float3 wi) {
  wo = normalize_or(wo, (float3)(0.0f));
  wi = normalize_or(wi, (float3)(0.0f));
  if (bsdf_flip_side(b, wo)) {
    wo.z = -wo.z;
    wi.z = -wi.z;
  }
  float p = 0.0f;
  switch (b->type) {
#ifdef GDR_USE_DIFFUSE
    case BSDF_DIFFUSE: p = diffuse_pdf(b, wo, wi); break;
#endif
#ifdef GDR_USE_ROUGH_CONDUCTOR
    case BSDF_ROUGH_CONDUCTOR: p = rough_conductor_pdf(b, wo, wi); break;
#endif
#ifdef GDR_USE_ROUGH_DIELECTRIC
    case BSDF_ROUGH_DIELECTRIC: p = rough_dielectric_pdf(b, wo, wi); break;
#endif
#ifdef GDR_USE_PLASTIC
    case BSDF_PLASTIC: p = plastic_pdf(b, wo, wi); break;
#endif
#ifdef GDR_USE_ROUGH_PLASTIC
    case BSDF_ROUGH_PLASTIC: p = rough_plastic_pdf(b, wo, wi); break;
#endif
    default: break;
  }
  return fmax(finite_or_zero(p), 0.0f);
}

// Samples wi from three uniforms (u.x picks the lobe, u.yz the direction). Returns 0 when there
// is no sample (wrong side of a one-sided BSDF, zero weight, degenerate geometry).
__attribute__((always_inline)) inline int bsdf_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  wo = normalize_or(wo, (float3)(0.0f, 0.0f, 0.0f));
  if (dot(wo, wo) == 0.0f) return 0;
  int flip = bsdf_flip_side(b, wo);
  if (flip) wo.z = -wo.z;
  int ok = 0;
  switch (b->type) {
#ifdef GDR_USE_DIFFUSE
    case BSDF_DIFFUSE: ok = diffuse_sample(b, wo, u, s); break;
#endif
#ifdef GDR_USE_CONDUCTOR
    case BSDF_CONDUCTOR: ok = conductor_sample(b, wo, u, s); break;
#endif
#ifdef GDR_USE_ROUGH_CONDUCTOR
    case BSDF_ROUGH_CONDUCTOR: ok = rough_conductor_sample(b, wo, u, s); break;
#endif
#ifdef GDR_USE_DIELECTRIC
    case BSDF_DIELECTRIC: ok = dielectric_sample(b, wo, u, s); break;
#endif
#ifdef GDR_USE_THIN_DIELECTRIC
    case BSDF_THIN_DIELECTRIC: ok = thin_dielectric_sample(b, wo, u, s); break;
#endif
#ifdef GDR_USE_ROUGH_DIELECTRIC
    case BSDF_ROUGH_DIELECTRIC: ok = rough_dielectric_sample(b, wo, u, s); break;
#endif
#ifdef GDR_USE_PLASTIC
    case BSDF_PLASTIC: ok = plastic_sample(b, wo, u, s); break;
#endif
#ifdef GDR_USE_ROUGH_PLASTIC
    case BSDF_ROUGH_PLASTIC: ok = rough_plastic_sample(b, wo, u, s); break;
#endif
    default: break;
  }
  if (!ok) return 0;
  if (flip) s->wi.z = -s->wi.z;
  if (!is_finite3(s->wi) || !is_finite3(s->weight) || !(s->pdf > 0.0f) || !isfinite(s->pdf) ||
      !isfinite(s->eta)) {
    return 0;
  }
  s->weight = fmax(s->weight, (float3)(0.0f));
  return s->weight.x > 0.0f || s->weight.y > 0.0f || s->weight.z > 0.0f;
}

// All components are delta (no bsdf_eval / bsdf_pdf contribution).
inline int bsdf_is_delta(const Bsdf* b) { return material_is_delta(b->type, b->eta.x); }

// Some component is delta (smooth plastic's coating reflection, besides the pure delta types).
inline int bsdf_has_delta_lobe(const Bsdf* b) { return material_has_delta_lobe(b->type, b->eta.x); }

inline int bsdf_has_diffuse_lobe(const Bsdf* b) { return material_has_diffuse_lobe(b->type); }

// Roughness that decides how gradient-domain shifts treat the vertex (shared/material_class.h).
inline float bsdf_roughness(const Bsdf* b) {
  return material_roughness(b->type, b->eta.x, b->alpha_u, b->alpha_v);
}
