// Fresnel equations: dielectric interfaces (with the refracted direction's cosine and the
// relative IORs), conductors (complex IOR), and the diffuse (hemispherical) reflectance fit.
#pragma once
#include "core/math.h"

// Unpolarized Fresnel reflectance of a dielectric interface with relative IOR eta = int / ext.
// cos_theta_i > 0: arriving from outside; < 0: from inside (eta inverted). Outputs the signed
// cosine of the refracted direction (opposite sign to cos_theta_i; 0 under total internal
// reflection), eta_it (IOR of the transmitted side / incident side) and eta_ti = 1 / eta_it.
// Index-matched (eta == 1) gives 0; grazing incidence (cos == 0) gives 1. name_r: the reflectance
// alone. Written once for values of type F with masks of type I (float and int; float8 and int8
// for lane kernels, bsdf/bsdf_lanes.h): its cases are selects.
#define FRESNEL_DIELECTRIC(name, name_r, F, I)                                                          \
  inline F name(F cos_theta_i, F eta, F* cos_theta_t, F* eta_it, F* eta_ti) {                           \
    I outside = cos_theta_i >= 0.0f;                                                                    \
    F rcp_eta = 1.0f / eta;                                                                             \
    *eta_it = select(rcp_eta, eta, outside);                                                            \
    *eta_ti = select(eta, rcp_eta, outside);                                                            \
    F ci = fmin(fabs(cos_theta_i), 1.0f);                                                               \
    F cos_t2 = 1.0f - *eta_ti * *eta_ti * (1.0f - ci * ci);                                             \
    F ct = sqrt(fmax(cos_t2, 0.0f));                                                                    \
    I total = ((ci == 0.0f) | (cos_t2 <= 0.0f)) & (eta != 1.0f); /* grazing or total reflection */      \
    *cos_theta_t = select(select(ct, -ct, outside), (F)(0.0f), total);                                  \
    F e = *eta_it;                                                                                      \
    F a_s = (ci - e * ct) / (ci + e * ct);                                                              \
    F a_p = (ct - e * ci) / (ct + e * ci);                                                              \
    F r = select(clamp(0.5f * (a_s * a_s + a_p * a_p), 0.0f, 1.0f), (F)(1.0f), total);                  \
    return select(r, (F)(0.0f), eta == 1.0f);                                                           \
  }                                                                                                     \
  inline F name_r(F cos_theta_i, F eta) {                                                               \
    F ct, eit, eti;                                                                                     \
    return name(cos_theta_i, eta, &ct, &eit, &eti);                                                     \
  }
FRESNEL_DIELECTRIC(fresnel_dielectric, fresnel_dielectric_r, float, int)

// Refraction of w (pointing away from the surface) through the interface with unit normal m;
// cos_theta_t and eta_ti come from fresnel_dielectric(dot(w, m), ...).
inline float3 refract_about(float3 w, float3 m, float cos_theta_t, float eta_ti) {
  return m * (dot(w, m) * eta_ti + cos_theta_t) - w * eta_ti;
}

// Unpolarized Fresnel reflectance of a conductor with complex relative IOR eta + i k, for
// cos_theta_i >= 0 (Mitsuba's formulation). A channel with eta <= 0 reflects fully: the
// "none" material (perfect mirror).
inline float fresnel_conductor1(float cos_theta_i, float eta, float k) {
  if (eta <= 0.0f) return 1.0f;
  float c = clamp(cos_theta_i, 0.0f, 1.0f);
  float c2 = c * c, s2 = 1.0f - c2, s4 = s2 * s2;
  float temp1 = eta * eta - k * k - s2;
  float a2pb2 = safe_sqrt(temp1 * temp1 + 4.0f * k * k * eta * eta);
  float a = safe_sqrt(0.5f * (a2pb2 + temp1));
  float term1 = a2pb2 + c2, term2 = 2.0f * c * a;
  float rs = safe_div(term1 - term2, term1 + term2);
  float term3 = a2pb2 * c2 + s4, term4 = term2 * s2;
  float rp = rs * safe_div(term3 - term4, term3 + term4);
  // Both ratios are 0/0 only at grazing incidence with eta = k = 0, where a mirror reflects fully.
  if (term1 + term2 == 0.0f) return 1.0f;
  return clamp(0.5f * (rs + rp), 0.0f, 1.0f);
}

inline float3 fresnel_conductor(float cos_theta_i, float3 eta, float3 k) {
  return (float3)(fresnel_conductor1(cos_theta_i, eta.x, k.x),
                  fresnel_conductor1(cos_theta_i, eta.y, k.y),
                  fresnel_conductor1(cos_theta_i, eta.z, k.z));
}

// Hemispherical (cosine-weighted) Fresnel reflectance for light arriving from the side with
// relative IOR eta = transmitted / incident: Egan & Hilgeman (1973) for eta < 1, d'Eon & Irving
// (2011) for eta >= 1 (the choice Mitsuba makes; about 0.1% error for IORs up to 2).
inline float fresnel_diffuse_reflectance(float eta) {
  float inv_eta = 1.0f / eta;
  float approx1 = 0.0636f * inv_eta + eta * (eta * -1.4399f + 0.7099f) + 0.6681f;
  float x = inv_eta;
  float approx2 =
      0.919317f + x * (-3.4793f + x * (6.75335f + x * (-7.80989f + x * (4.98554f + x * -1.36881f))));
  return clamp(eta < 1.0f ? approx1 : approx2, 0.0f, 1.0f);
}
