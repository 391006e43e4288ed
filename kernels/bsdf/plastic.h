// Plastics (Mitsuba's "plastic" and "roughplastic"): a diffuse base under a dielectric coating
// with relative IOR eta = eta.x. Light entering the coating (transmittance t(wo)) scatters
// diffusely with internal reflections at the coating, R_int; `nonlinear` lets the base albedo
// take part in those (colour shift): diffuse / (1 - diffuse R_int), else diffuse / (1 - R_int).
// Directions are already on the upper side (see bsdf.h).
#pragma once
#include "bsdf/bsdf_types.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "core/warp.h"

inline float3 plastic_base(const Bsdf* b) {
  float3 d = b->diffuse;
  float3 denom = b->nonlinear ? 1.0f - d * b->internal_reflectance
                              : (float3)(1.0f - b->internal_reflectance);
  return d / fmax(denom, (float3)(1e-4f));
}

// Probability of choosing the specular lobe given the coating's reflectance toward wo.
inline float plastic_specular_probability(const Bsdf* b, float reflect) {
  float ps = reflect * b->specular_weight;
  float pd = (1.0f - reflect) * (1.0f - b->specular_weight);
  return ps + pd > 0.0f ? ps / (ps + pd) : 0.0f;
}

// ---- Smooth coating: delta reflection + diffuse refracted through a smooth interface.

inline float3 plastic_eval(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return (float3)(0.0f);
  float eta = b->eta.x;
  float t_o = 1.0f - fresnel_dielectric_r(wo.z, eta);
  float t_i = 1.0f - fresnel_dielectric_r(wi.z, eta);
  return finite_or_zero3(plastic_base(b) *
                         (square_to_cosine_hemisphere_pdf(wi) * t_o * t_i / sqr(eta)));
}

inline float plastic_pdf(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
  float ps = plastic_specular_probability(b, fresnel_dielectric_r(wo.z, b->eta.x));
  return (1.0f - ps) * square_to_cosine_hemisphere_pdf(wi);
}

inline int plastic_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  if (!(wo.z > 0.0f)) return 0;
  float r_o = fresnel_dielectric_r(wo.z, b->eta.x);
  float ps = plastic_specular_probability(b, r_o);
  s->transmitted = 0;
  s->eta = 1.0f;
  if (u.x < ps) {
    s->wi = reflect_local(wo);
    s->pdf = ps;
    s->weight = b->specular_r * (r_o / ps);
    s->delta = 1;
    return 1;
  }
  float3 wi = square_to_cosine_hemisphere(u.yz);
  if (!(wi.z > 0.0f)) return 0;
  s->wi = wi;
  s->pdf = (1.0f - ps) * square_to_cosine_hemisphere_pdf(wi);
  float t_i = 1.0f - fresnel_dielectric_r(wi.z, b->eta.x);
  s->weight = finite_or_zero3(plastic_base(b) * ((1.0f - r_o) * t_i / (sqr(b->eta.x) * (1.0f - ps))));
  s->delta = 0;
  return s->pdf > 0.0f;
}

// ---- Rough coating: microfacet reflection + diffuse refracted through the rough interface.

// Fraction of light from w (upper side) that enters the rough coating: 1 - E[F(w.m)] over the
// normals visible from w. It bounds the light the specular lobe does not reflect (E[F G1]), so
// the lobes sum to <= 1. A fixed 4 x 4 midpoint rule on the GGX visible-normal warp (spherical
// caps; Beckmann uses the GGX warp of the same alpha as a proxy: the Fresnel average barely
// depends on the tails, and the exact Beckmann warp costs a Newton solve per node).
inline float rough_coating_transmittance(float au, float av, float eta, float3 w) {
  if (!(w.z > 0.0f)) return 0.0f;
  const float c = 0.70710678f;
  const float cphi[4] = {c, -c, -c, c}, sphi[4] = {c, c, -c, -c};
  float3 w_std = normalize_or((float3)(au * w.x, av * w.y, w.z), (float3)(0.0f, 0.0f, 1.0f));
  float sum = 0.0f;
  for (int j = 0; j < 4; ++j) {
    float z = (1.0f - (j + 0.5f) * 0.25f) * (1.0f + w_std.z) - w_std.z;
    float st = safe_sqrt(1.0f - z * z);
    for (int i = 0; i < 4; ++i) {
      float3 h = (float3)(st * cphi[i], st * sphi[i], z) + w_std;
      float3 m = normalize_or((float3)(au * h.x, av * h.y, fmax(h.z, 0.0f)),
                              (float3)(0.0f, 0.0f, 1.0f));
      sum += fresnel_dielectric_r(dot(w, m), eta);
    }
  }
  return clamp(1.0f - sum * (1.0f / 16.0f), 0.0f, 1.0f);
}

// Internal diffuse reflectance of the rough coating, from the reciprocity of transmission:
// 1 - R_int = (1 / eta^2) * 2 * integral_0^1 t(mu) mu dmu (6-point Gauss-Legendre in mu, at the
// geometric-mean roughness: an isotropic average).
inline float rough_coating_internal_reflectance(float alpha, float eta) {
  const float x[6] = {0.0337652429f, 0.1693953068f, 0.3806904070f,
                      0.6193095930f, 0.8306046932f, 0.9662347571f};
  const float wgt[6] = {0.0856622462f, 0.1803807865f, 0.2339569673f,
                        0.2339569673f, 0.1803807865f, 0.0856622462f};
  float sum = 0.0f;
  for (int i = 0; i < 6; ++i) {
    float mu = x[i];
    float3 w = (float3)(safe_sqrt(1.0f - mu * mu), 0.0f, mu);
    sum += wgt[i] * mu * rough_coating_transmittance(alpha, alpha, eta, w);
  }
  return clamp(1.0f - 2.0f * sum / sqr(eta), 0.0f, 0.9999f);
}

inline float rough_plastic_specular_pdf(const Bsdf* b, float3 wo, float3 wi) {
  float3 h;
  if (!half_vector_reflect(wo, wi, &h)) return 0.0f;
  return microfacet_pdf_visible(b->distribution, b->alpha_u, b->alpha_v, wo, h) *
         half_jacobian_reflect(wi, h);
}

// t_o = rough_coating_transmittance toward wo (passed in so sampling computes it once).
inline float3 rough_plastic_eval_t(const Bsdf* b, float3 wo, float3 wi, float t_o) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return (float3)(0.0f);
  int t = b->distribution;
  float au = b->alpha_u, av = b->alpha_v, eta = b->eta.x;
  float3 value = (float3)(0.0f);
  float3 h;
  if (half_vector_reflect(wo, wi, &h)) {
    float d = microfacet_D(t, au, av, h);
    float g = microfacet_G(t, au, av, wo, wi, h);
    float f = fresnel_dielectric_r(dot(wo, h), eta);
    value = b->specular_r * safe_div(f * d * g, 4.0f * wo.z);
  }
  float t_i = rough_coating_transmittance(au, av, eta, wi);
  value += plastic_base(b) * (square_to_cosine_hemisphere_pdf(wi) * t_o * t_i / sqr(eta));
  return finite_or_zero3(value);
}

inline float rough_plastic_pdf_t(const Bsdf* b, float3 wo, float3 wi, float t_o) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
  float ps = plastic_specular_probability(b, 1.0f - t_o);
  return finite_or_zero(ps * rough_plastic_specular_pdf(b, wo, wi) +
                        (1.0f - ps) * square_to_cosine_hemisphere_pdf(wi));
}

inline float3 rough_plastic_eval(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return (float3)(0.0f);
  float t_o = rough_coating_transmittance(b->alpha_u, b->alpha_v, b->eta.x, wo);
  return rough_plastic_eval_t(b, wo, wi, t_o);
}

inline float rough_plastic_pdf(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
  float t_o = rough_coating_transmittance(b->alpha_u, b->alpha_v, b->eta.x, wo);
  return rough_plastic_pdf_t(b, wo, wi, t_o);
}

inline int rough_plastic_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  if (!(wo.z > 0.0f)) return 0;
  float t_o = rough_coating_transmittance(b->alpha_u, b->alpha_v, b->eta.x, wo);
  float ps = plastic_specular_probability(b, 1.0f - t_o);
  float3 wi;
  if (u.x < ps) {
    float3 m = microfacet_sample_visible(b->distribution, b->alpha_u, b->alpha_v, wo, u.yz);
    wi = reflect_about(wo, m);
  } else {
    wi = square_to_cosine_hemisphere(u.yz);
  }
  if (!(wi.z > 0.0f)) return 0;
  float pdf = rough_plastic_pdf_t(b, wo, wi, t_o);
  if (!(pdf > 0.0f)) return 0;
  s->wi = wi;
  s->pdf = pdf;
  s->weight = finite_or_zero3(rough_plastic_eval_t(b, wo, wi, t_o) / pdf);
  s->delta = 0;
  s->transmitted = 0;
  s->eta = 1.0f;
  return 1;
}
