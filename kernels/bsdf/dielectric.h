// Dielectrics (Mitsuba's "dielectric", "thindielectric", "roughdielectric"). Two-sided by
// nature: wo.z < 0 means wo lies inside and the relative IOR is inverted. eta = eta.x =
// int_ior / ext_ior. Transmission carries the radiance scaling 1 / eta_rel^2 (radiance
// transport: the camera-side direction is wo); multiply a transmitted weight by eta^2 of the
// sample to get the importance (light-transport) form.
#pragma once
#include "bsdf/bsdf_types.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"

// An index-matched rough dielectric lets light pass straight through (its refraction half vector
// would be undefined).
inline int dielectric_index_matched(const Bsdf* b) { return material_index_matched(BSDF_ROUGH_DIELECTRIC, b->eta.x); }

inline int dielectric_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  float ct, eta_it, eta_ti;
  float r = fresnel_dielectric(wo.z, b->eta.x, &ct, &eta_it, &eta_ti);
  s->delta = 1;
  if (u.x < r) {
    s->wi = reflect_local(wo);
    s->pdf = r;
    s->weight = b->specular_r;
    s->transmitted = 0;
    s->eta = 1.0f;
  } else {
    s->wi = normalize_or((float3)(-eta_ti * wo.x, -eta_ti * wo.y, ct), -wo);
    s->pdf = 1.0f - r;
    s->weight = b->specular_t * sqr(eta_ti);
    s->transmitted = 1;
    s->eta = eta_it;
  }
  return s->pdf > 0.0f;
}

// A thin sheet: reflection with the sum of all inter-reflections inside it, R' = 2R / (1 + R);
// transmission passes straight through (wi = -wo).
inline int thin_dielectric_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  float r = fresnel_dielectric_r(fabs(wo.z), b->eta.x);
  r = r < 1.0f ? 2.0f * r / (1.0f + r) : 1.0f;
  s->delta = 1;
  s->eta = 1.0f;
  if (u.x < r) {
    s->wi = reflect_local(wo);
    s->pdf = r;
    s->weight = b->specular_r;
    s->transmitted = 0;
  } else {
    s->wi = -wo;
    s->pdf = 1.0f - r;
    s->weight = b->specular_t;
    s->transmitted = 1;
  }
  return s->pdf > 0.0f;
}

// Index-matched rough dielectric: a delta transmission.
inline int pass_through_sample(const Bsdf* b, float3 wo, BsdfSample* s) {
  s->wi = -wo;
  s->pdf = 1.0f;
  s->weight = b->specular_t;
  s->delta = 1;
  s->transmitted = 1;
  s->eta = 1.0f;
  return 1;
}

// Shared by eval and pdf: the (generalized) half vector of wo -> wi, oriented to +z, with
// eta_rel = IOR on wi's side / IOR on wo's side. Returns 0 where no microfacet connects them.
inline int rough_dielectric_half(const Bsdf* b, float3 wo, float3 wi, float3* h, float* eta_rel) {
  if (wo.z == 0.0f || wi.z == 0.0f) return 0;
  int reflect = wo.z * wi.z > 0.0f;
  float eta = b->eta.x;
  *eta_rel = reflect ? 1.0f : (wo.z > 0.0f ? eta : 1.0f / eta);
  int ok = reflect ? half_vector_reflect(wo, wi, h) : half_vector_refract(wo, wi, *eta_rel, h);
  // Both directions must see the front of the microfacet from their own side.
  return ok && dot(wo, *h) * wo.z > 0.0f && dot(wi, *h) * wi.z > 0.0f;
}

inline float3 rough_dielectric_eval(const Bsdf* b, float3 wo, float3 wi) {
  if (dielectric_index_matched(b)) return (float3)(0.0f);
  float3 h;
  float eta_rel;
  if (!rough_dielectric_half(b, wo, wi, &h, &eta_rel)) return (float3)(0.0f);
  int t = b->distribution;
  float d = microfacet_D(t, b->alpha_u, b->alpha_v, h);
  if (d == 0.0f) return (float3)(0.0f);
  float g = microfacet_G(t, b->alpha_u, b->alpha_v, wo, wi, h);
  float f = fresnel_dielectric_r(dot(wo, h), b->eta.x);
  float cos_o = fabs(wo.z);
  if (wo.z * wi.z > 0.0f) {
    return finite_or_zero3(b->specular_r * safe_div(f * d * g, 4.0f * cos_o));
  }
  // Walter et al.'s BTDF times |cos wi|, with the radiance scaling 1 / eta_rel^2 (which cancels
  // the eta_rel^2 of the Jacobian).
  float wo_h = dot(wo, h), wi_h = dot(wi, h);
  float value = safe_div((1.0f - f) * d * g * fabs(wo_h * wi_h),
                         cos_o * sqr(wo_h + eta_rel * wi_h));
  return finite_or_zero3(b->specular_t * value);
}

inline float rough_dielectric_pdf(const Bsdf* b, float3 wo, float3 wi) {
  if (dielectric_index_matched(b)) return 0.0f;
  float3 h;
  float eta_rel;
  if (!rough_dielectric_half(b, wo, wi, &h, &eta_rel)) return 0.0f;
  int reflect = wo.z * wi.z > 0.0f;
  float3 wo_up = wo.z > 0.0f ? wo : -wo;
  float pdf_m = microfacet_pdf_visible(b->distribution, b->alpha_u, b->alpha_v, wo_up, h);
  float f = fresnel_dielectric_r(dot(wo, h), b->eta.x);
  float jac = reflect ? half_jacobian_reflect(wi, h) : half_jacobian_refract(wo, wi, h, eta_rel);
  return finite_or_zero(pdf_m * (reflect ? f : 1.0f - f) * jac);
}

inline int rough_dielectric_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  if (dielectric_index_matched(b)) return pass_through_sample(b, wo, s);
  if (wo.z == 0.0f) return 0;
  int t = b->distribution;
  float au = b->alpha_u, av = b->alpha_v;
  float3 wo_up = wo.z > 0.0f ? wo : -wo;
  float3 m = microfacet_sample_visible(t, au, av, wo_up, u.yz);
  float pdf_m = microfacet_pdf_visible(t, au, av, wo_up, m);
  if (!(pdf_m > 0.0f)) return 0;
  float ct, eta_it, eta_ti;
  float f = fresnel_dielectric(dot(wo, m), b->eta.x, &ct, &eta_it, &eta_ti);
  float3 wi;
  float pdf;
  if (u.x < f) {
    wi = reflect_about(wo, m);
    if (!(wi.z * wo.z > 0.0f)) return 0;
    pdf = pdf_m * f * half_jacobian_reflect(wi, m);
    s->weight = b->specular_r;
    s->transmitted = 0;
    s->eta = 1.0f;
  } else {
    wi = normalize_or(refract_about(wo, m, ct, eta_ti), -wo);
    if (!(wi.z * wo.z < 0.0f)) return 0;
    pdf = pdf_m * (1.0f - f) * half_jacobian_refract(wo, wi, m, eta_it);
    s->weight = b->specular_t * sqr(eta_ti);
    s->transmitted = 1;
    s->eta = eta_it;
  }
  // Visible-normal sampling and Fresnel-proportional lobe choice leave G1(wi) as the weight.
  float g1 = microfacet_G1(t, au, av, wi, m);
  if (!(pdf > 0.0f) || !isfinite(pdf) || g1 == 0.0f) return 0;
  s->wi = wi;
  s->weight = finite_or_zero3(s->weight * g1);
  s->pdf = pdf;
  s->delta = 0;
  return 1;
}
