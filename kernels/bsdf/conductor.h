// Conductors (Mitsuba's "conductor" and "roughconductor"): complex Fresnel reflection scaled by
// specular_reflectance; smooth is a delta mirror, rough a Cook-Torrance microfacet lobe sampled
// through visible normals. Directions are already on the upper side (see bsdf.h).
#pragma once
#include "bsdf/bsdf_types.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"

inline int conductor_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  if (!(wo.z > 0.0f)) return 0;
  s->wi = reflect_local(wo);
  s->weight = b->specular_r * fresnel_conductor(wo.z, b->eta, b->k);
  s->pdf = 1.0f;
  s->delta = 1;
  s->transmitted = 0;
  s->eta = 1.0f;
  return 1;
}

inline float3 rough_conductor_eval(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return (float3)(0.0f);
  float3 h;
  if (!half_vector_reflect(wo, wi, &h)) return (float3)(0.0f);
  float d = microfacet_D(b->distribution, b->alpha_u, b->alpha_v, h);
  if (d == 0.0f) return (float3)(0.0f);
  float g = microfacet_G(b->distribution, b->alpha_u, b->alpha_v, wo, wi, h);
  float3 f = fresnel_conductor(dot(wo, h), b->eta, b->k);
  // f(wo, wi) cos(wi) = F D G / (4 cos(wo)).
  return finite_or_zero3(b->specular_r * f * safe_div(d * g, 4.0f * wo.z));
}

inline float rough_conductor_pdf(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
  float3 h;
  if (!half_vector_reflect(wo, wi, &h)) return 0.0f;
  return microfacet_pdf_visible(b->distribution, b->alpha_u, b->alpha_v, wo, h) *
         half_jacobian_reflect(wi, h);
}

inline int rough_conductor_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  if (!(wo.z > 0.0f)) return 0;
  int t = b->distribution;
  float3 m = microfacet_sample_visible(t, b->alpha_u, b->alpha_v, wo, u.yz);
  float3 wi = reflect_about(wo, m);
  if (!(wi.z > 0.0f)) return 0;
  float pdf = microfacet_pdf_visible(t, b->alpha_u, b->alpha_v, wo, m) *
              half_jacobian_reflect(wi, m);
  if (!(pdf > 0.0f) || !isfinite(pdf)) return 0;
  // With visible-normal sampling D and G1(wo) cancel: weight = F G1(wi).
  float3 w = b->specular_r * fresnel_conductor(dot(wo, m), b->eta, b->k) *
             microfacet_G1(t, b->alpha_u, b->alpha_v, wi, m);
  s->wi = wi;
  s->weight = finite_or_zero3(w);
  s->pdf = pdf;
  s->delta = 0;
  s->transmitted = 0;
  s->eta = 1.0f;
  return 1;
}
