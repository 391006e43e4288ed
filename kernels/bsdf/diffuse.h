// Lambertian reflection (Mitsuba's "diffuse"): f = R / pi, cosine-weighted sampling.
// Directions are already on the upper side (bsdf.h handles one- and two-sidedness).
#pragma once
#include "bsdf/bsdf_types.h"
#include "core/warp.h"

inline float3 diffuse_eval(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return (float3)(0.0f);
  return b->diffuse * (wi.z * M_1_PI_F);
}

inline float diffuse_pdf(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z > 0.0f && wi.z > 0.0f)) return 0.0f;
  return square_to_cosine_hemisphere_pdf(wi);
}

inline int diffuse_sample(const Bsdf* b, float3 wo, float3 u, BsdfSample* s) {
  if (!(wo.z > 0.0f)) return 0;
  float3 wi = square_to_cosine_hemisphere(u.yz);
  if (!(wi.z > 0.0f)) return 0;
  s->wi = wi;
  s->pdf = square_to_cosine_hemisphere_pdf(wi);
  s->weight = b->diffuse;
  s->delta = 0;
  s->transmitted = 0;
  s->eta = 1.0f;
  return 1;
}
