// Half-vector copy (Kettunen et al. 2015): the offset scatters about the half vector the base
// used, for glossy vertices that cannot be reconnected. Directions are unit vectors in the
// vertex's shading frame pointing away from it; wo toward the previous vertex, wi toward the next.
#pragma once
#include "bsdf/bsdf.h"

// The base scattered wo -> wi about half vector h (reflection, or refraction with relative IOR
// eta_rel = IOR on wi's side / IOR on wo's side); the offset, arriving from wo_off at a surface
// of relative IOR eta_material (int / ext), scatters about the same local h. Returns 0 where the
// offset cannot follow (total internal reflection in the offset only, or the offset direction
// leaves on the other side than the base's). *jacobian = |d wi_off / d wi|.
inline int shift_half_vector(float3 wo, float3 wi, int transmitted, float eta_rel, float3 wo_off,
                             float eta_material, float3* wi_off, float* jacobian) {
  float3 h;
  if (!transmitted) {
    if (!half_vector_reflect(wo, wi, &h)) return 0;
    float3 w = reflect_about(wo_off, h);
    if (!(w.z * wi.z > 0.0f) || !(wo_off.z * wo.z > 0.0f)) return 0;
    *wi_off = w;
    *jacobian = safe_div(half_jacobian_reflect(wi, h), half_jacobian_reflect(w, h));
    return *jacobian > 0.0f;
  }
  if (!half_vector_refract(wo, wi, eta_rel, &h)) return 0;
  if (!(wo_off.z * wo.z > 0.0f)) return 0;
  float ct, eta_it, eta_ti;
  float f = fresnel_dielectric(dot(wo_off, h), eta_material, &ct, &eta_it, &eta_ti);
  if (f >= 1.0f || ct == 0.0f) return 0;  // total internal reflection in the offset only
  float3 w = refract_about(wo_off, h, ct, eta_ti);
  if (!(w.z * wi.z > 0.0f)) return 0;
  w = normalize(w);
  *wi_off = w;
  *jacobian = safe_div(half_jacobian_refract(wo, wi, h, eta_rel), half_jacobian_refract(wo_off, w, h, eta_it));
  return *jacobian > 0.0f && isfinite(*jacobian);
}
