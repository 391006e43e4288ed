// Plastics (Mitsuba's "plastic" and "roughplastic"): a diffuse base under a dielectric coating
// with relative IOR eta = eta.x. Light entering the coating (transmittance t(wo)) scatters
// diffusely with internal reflections at the coating, R_int; `nonlinear` lets the base albedo
// take part in those (colour shift): diffuse / (1 - diffuse R_int), else diffuse / (1 - R_int).
// R_int, and t of the rough coating, come from the material's coating table (coating.h), built
// when the scene is uploaded; the smooth coating's t is 1 - F. Directions are already on the
// upper side (see bsdf.h).
#pragma once
#include "bsdf/bsdf_types.h"
#include "bsdf/coating.h"
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "core/warp.h"

inline float3 plastic_base(const Bsdf* b) {
  float3 d = b->diffuse;
  float3 denom = b->nonlinear ? 1.0f - d * b->internal_reflectance
                              : (float3)(1.0f - b->internal_reflectance);
  return d / fmax(denom, (float3)(1e-4f));
}

// Probability of choosing the specular lobe given the coating's reflectance toward wo and the
// material's specular weight; for values of type F (float; float8 in bsdf/bsdf_lanes.h).
#define PLASTIC_SPECULAR_PROBABILITY(name, F)                  \
  inline F name(F reflect, F specular_weight) {                \
    F ps = reflect * specular_weight;                          \
    F pd = (1.0f - reflect) * (1.0f - specular_weight);        \
    return select((F)(0.0f), ps / (ps + pd), ps + pd > 0.0f);  \
  }
PLASTIC_SPECULAR_PROBABILITY(plastic_lobe_probability, float)

inline float plastic_specular_probability(const Bsdf* b, float reflect) {
  return plastic_lobe_probability(reflect, b->specular_weight);
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

// Density of wi through the specular lobe: the visible normals' D G1(wo, h) (wo.h) / wo.z times
// the reflection's Jacobian 1 / (4 wi.h). The dot products cancel (wo.h = wi.h), so it is
// written D G1 / (4 wo.z), as Mitsuba does: at grazing wo the two dot products of a half vector
// rounded from float directions can differ by orders of magnitude, and the sample weight
// (F G1(wi, h) for this lobe) would no longer be bounded by 1.
inline float rough_plastic_specular_pdf(const Bsdf* b, float3 wo, float3 wi) {
  float3 h;
  if (!half_vector_reflect(wo, wi, &h)) return 0.0f;
  int t = b->distribution;
  float d = microfacet_D(t, b->alpha_u, b->alpha_v, h);
  return safe_div(d * microfacet_G1(t, b->alpha_u, b->alpha_v, wo, h), 4.0f * wo.z);
}

// t_o = the coating's transmittance toward wo (passed in so sampling reads it once).
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
  float t_i = coating_transmittance(b->coating, wi.z);
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
  float t_o = coating_transmittance(b->coating, wo.z);
  return rough_plastic_eval_t(b, wo, wi, t_o);
}

inline float rough_plastic_pdf(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
  float t_o = coating_transmittance(b->coating, wo.z);
  return rough_plastic_pdf_t(b, wo, wi, t_o);
}

inline int rough_plastic_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  if (!(wo.z > 0.0f)) return 0;
  float t_o = coating_transmittance(b->coating, wo.z);
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
