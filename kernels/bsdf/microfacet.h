// Microfacet distributions (Beckmann, GGX; anisotropic alpha_u along x, alpha_v along y):
// the normal distribution D, Smith's exact masking G1, sampling of visible normals, its pdf,
// and the reflection / generalized refraction half vectors and their Jacobians, which the
// gradient-domain shifts reuse.
#pragma once
#include "core/frame.h"
#include "core/math.h"
#include "shared/material_class.h"
#include "shared/scene_types.h"

inline float microfacet_D(int type, float au, float av, float3 m) {
  float c2 = m.z * m.z;
  if (!(m.z > 0.0f)) return 0.0f;
  float xy = sqr(m.x / au) + sqr(m.y / av);
  float result;
  if (type == MICROFACET_BECKMANN) {
    float e = xy / c2;
    // exp underflows long before the denominator does; skip it to avoid 0/0 at grazing m.
    if (e > 80.0f) return 0.0f;
    result = exp(-e) / (M_PI_F * au * av * c2 * c2);
  } else {
    result = 1.0f / (M_PI_F * au * av * sqr(xy + c2));
  }
  return (result * m.z > 1e-20f) ? finite_or_zero(result) : 0.0f;
}

// Smith masking of direction v for microfacet normal m (exact for both distributions); 0 when v
// sees the back of m or lies in the tangent plane.
inline float microfacet_G1(int type, float au, float av, float3 v, float3 m) {
  if (!(dot(v, m) * v.z > 0.0f)) return 0.0f;
  float xy_alpha2 = sqr(au * v.x) + sqr(av * v.y);
  if (xy_alpha2 == 0.0f) return 1.0f;
  float tan_alpha2 = xy_alpha2 / sqr(v.z);  // may be +Inf at grazing v: G1 -> 0 below
  float result;
  if (type == MICROFACET_BECKMANN) {
    float a = rsqrt(tan_alpha2);  // 1 / (alpha tan theta)
    if (!(a > 0.0f)) return 0.0f;
    result = 2.0f / (1.0f + erf(a) + exp(-a * a) * GDR_INV_SQRT_PI / a);
  } else {
    result = 2.0f / (1.0f + sqrt(1.0f + tan_alpha2));
  }
  return clamp(finite_or_zero(result), 0.0f, 1.0f);
}

inline float microfacet_G(int type, float au, float av, float3 wo, float3 wi, float3 m) {
  return microfacet_G1(type, au, av, wo, m) * microfacet_G1(type, au, av, wi, m);
}

// Visible slopes of the Beckmann distribution with alpha = 1 seen from elevation cos_theta
// (Jakob 2014): the x slope inverts the marginal CDF in the erf domain by safeguarded Newton
// steps (bisection when a step leaves the bracket), the y slope is Gaussian.
inline float2 beckmann_visible_slopes_11(float cos_theta, float2 u) {
  u = clamp(u, 1e-6f, 1.0f - 1e-6f);
  cos_theta = clamp(cos_theta, 1e-6f, 1.0f);  // horizon: keep tan finite
  float tan_theta = safe_sqrt(1.0f - cos_theta * cos_theta) / cos_theta;
  float cot_theta = 1.0f / tan_theta;  // +Inf at normal incidence: erf(Inf) = 1, exp(-Inf) = 0
  float maxval = erf(cot_theta);
  float tail = tan_theta > 0.0f ? GDR_INV_SQRT_PI * tan_theta * exp(-cot_theta * cot_theta) : 0.0f;
  float norm = 1.0f + maxval + tail;
  float target = u.x * norm;
  float lo = -1.0f, hi = maxval;
  // Initial guess: inverse of an approximation of the CDF (Mitsuba).
  float x = maxval - (maxval + 1.0f) * erf(sqrt(-log(u.x)));
  // The residual bottoms out at float precision (~1e-7 of the CDF): keep the best iterate and
  // stop when a step no longer moves x, instead of bisecting away from the root.
  float best_x = clamp(x, lo, hi), best_v = INFINITY;
  for (int i = 0; i < 16; ++i) {
    if (!(x > lo && x < hi)) x = 0.5f * (lo + hi);
    float slope = erfinv_approx(x);
    float value = 1.0f + x + GDR_INV_SQRT_PI * tan_theta * exp(-slope * slope) - target;
    if (fabs(value) < best_v) {
      best_v = fabs(value);
      best_x = x;
    }
    if (value > 0.0f) hi = x; else lo = x;
    if (best_v < 2e-7f * norm) break;  // u reproduced to 2e-7
    float derivative = 1.0f - slope * tan_theta;
    float step = value / derivative;
    float next = (derivative > 0.0f && isfinite(step)) ? x - step : 0.5f * (lo + hi);
    if (next == x) break;
    x = next;
  }
  x = clamp(best_x, -1.0f + 1e-7f, fmin(maxval, 1.0f - 1e-7f));
  return (float2)(erfinv_approx(x), erfinv_approx(2.0f * u.y - 1.0f));
}

// Samples a microfacet normal from the distribution of normals visible from w (w.z > 0):
// density D(m) G1(w, m) max(0, w.m) / w.z. GGX uses spherical caps (Dupuy & Benyoub 2023).
inline float3 microfacet_sample_visible(int type, float au, float av, float3 w, float2 u) {
  float3 w_std = normalize_or((float3)(au * w.x, av * w.y, w.z), (float3)(0.0f, 0.0f, 1.0f));
  if (type == MICROFACET_BECKMANN) {
    float2 sc = sincos_phi(w_std);
    float2 s = beckmann_visible_slopes_11(clamp(w_std.z, 0.0f, 1.0f), u);
    float sx = (sc.y * s.x - sc.x * s.y) * au;
    float sy = (sc.x * s.x + sc.y * s.y) * av;
    return normalize_or((float3)(-sx, -sy, 1.0f), (float3)(0.0f, 0.0f, 1.0f));
  }
  float phi = 2.0f * M_PI_F * u.x;
  float z = (1.0f - u.y) * (1.0f + w_std.z) - w_std.z;
  float sin_theta = safe_sqrt(1.0f - z * z);
  float3 h_std = (float3)(sin_theta * cos(phi), sin_theta * sin(phi), z) + w_std;
  return normalize_or((float3)(au * h_std.x, av * h_std.y, fmax(h_std.z, 0.0f)),
                      (float3)(0.0f, 0.0f, 1.0f));
}

// Density (solid angle of m) of microfacet_sample_visible.
inline float microfacet_pdf_visible(int type, float au, float av, float3 w, float3 m) {
  if (!(w.z > 0.0f)) return 0.0f;
  float d = microfacet_D(type, au, av, m);
  if (d == 0.0f) return 0.0f;
  return safe_div(d * microfacet_G1(type, au, av, w, m) * fabs(dot(w, m)), w.z);
}

// Half vector of a reflection wo -> wi, oriented to +z. Returns 0 when undefined (wi == -wo).
inline int half_vector_reflect(float3 wo, float3 wi, float3* h) {
  float3 s = wo + wi;
  if (!(dot(s, s) > 1e-20f)) return 0;
  float3 n = normalize(s);
  *h = n.z < 0.0f ? -n : n;
  return 1;
}

// Generalized half vector of a refraction wo -> wi (Walter et al. 2007): h ~ wo + eta_rel wi,
// where eta_rel = IOR on wi's side / IOR on wo's side; oriented to +z. Returns 0 when undefined
// (index-matched straight transmission, where wo + wi == 0).
inline int half_vector_refract(float3 wo, float3 wi, float eta_rel, float3* h) {
  float3 s = wo + eta_rel * wi;
  if (!(dot(s, s) > 1e-12f)) return 0;
  float3 n = normalize(s);
  *h = n.z < 0.0f ? -n : n;
  return 1;
}

// Jacobian |d h / d wi| of the reflection half vector: 1 / (4 |wi.h|).
inline float half_jacobian_reflect(float3 wi, float3 h) {
  return safe_div(1.0f, 4.0f * fabs(dot(wi, h)));
}

// Jacobian |d h / d wi| of the generalized refraction half vector:
// eta_rel^2 |wi.h| / (wo.h + eta_rel wi.h)^2.
inline float half_jacobian_refract(float3 wo, float3 wi, float3 h, float eta_rel) {
  return safe_div(sqr(eta_rel) * fabs(dot(wi, h)), sqr(dot(wo, h) + eta_rel * dot(wi, h)));
}
