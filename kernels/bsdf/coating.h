// The plastics' dielectric coating as Mitsuba 3 tabulates it (microfacet.h: eval_transmittance,
// eval_reflectance; roughplastic.cpp): the integrands that kernels/bsdf/coating_tables.cl
// averages over visible normals when a scene is uploaded, and the reads of the resulting table
// (layout: shared/coating_table.h) by the BSDFs.
#pragma once
#include "bsdf/fresnel.h"
#include "bsdf/microfacet.h"
#include "core/frame.h"
#include "shared/coating_table.h"

// Light from w (outside, w.z > 0) meets the normal m drawn from the normals visible from w with
// the uniforms u: the part (1 - F) refracted into the coating that is not masked on its way in,
// G1(w_t, m). Its mean over u is the external transmittance t(w.z).
inline float coating_transmittance_sample(int type, float alpha, float eta, float3 w, float2 u) {
  float3 m = microfacet_sample_visible(type, alpha, alpha, w, u);
  float w_m = dot(w, m);
  if (!(w_m > 0.0f)) return 0.0f;
  float cos_t, eta_it, eta_ti;
  float f = fresnel_dielectric(w_m, eta, &cos_t, &eta_it, &eta_ti);
  float3 wt = refract_about(w, m, cos_t, eta_ti);
  if (!(f < 1.0f && wt.z < 0.0f)) return 0.0f;
  return (1.0f - f) * microfacet_G1(type, alpha, alpha, wt, m);
}

// The same for reflection toward a medium of relative IOR eta: F(w.m) G1(w_r, m) where w_r
// stays above the surface. With eta = 1 / eta_coating and its mean over u, the reflectance of
// the coating for light inside it.
inline float coating_reflectance_sample(int type, float alpha, float eta, float3 w, float2 u) {
  float3 m = microfacet_sample_visible(type, alpha, alpha, w, u);
  float w_m = dot(w, m);
  float3 wr = reflect_about(w, m);
  if (!(w_m > 0.0f && wr.z > 0.0f)) return 0.0f;
  return fresnel_dielectric_r(w_m, eta) * microfacet_G1(type, alpha, alpha, wr, m);
}

// Gauss-Legendre points per axis of the visible-normal quadrature for relative IOR eta:
// Mitsuba's choice, more where total internal reflection makes the integrand jump.
inline int coating_rule_points(float eta) { return eta > 1.0f ? 32 : 128; }

// t(cos_theta) from a rough coating's table: linear between the nodes, as Mitsuba's lerp_gather.
// A material without a table (coating == 0) transmits nothing.
inline float coating_transmittance(__global const float* coating, float cos_theta) {
  if (!coating) return 0.0f;
  float x = clamp(cos_theta, 0.0f, 1.0f) * (float)(GDR_COATING_NODES - 1);
  int i = min((int)x, GDR_COATING_NODES - 2);
  __global const float* t = coating + GDR_COATING_TRANSMITTANCE;
  return mix(t[i], t[i + 1], x - (float)i);
}

inline float coating_internal_reflectance(__global const float* coating) {
  return coating ? coating[GDR_COATING_INTERNAL_REFLECTANCE] : 0.0f;
}
