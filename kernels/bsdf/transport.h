// The BSDF call with its transport mode, for paths that start at the lights. bsdf.h is written
// for radiance transport (wo toward the camera, refraction scaled by 1 / eta^2). A light subpath
// carries importance the other way: at its vertices wo is the direction toward the light it came
// from and wi the one it continues along, toward the camera. Two things change (Veach's thesis,
// 5.2 and 5.3; pbrt-v4 issues #13 and #385 show what goes wrong without the second):
//   - refraction: the adjoint BTDF has no 1 / eta^2 (f*(wo, wi) = f(wi, wo)), so the radiance
//     form is multiplied by eta_rel^2 (eta_rel: IOR on wi's side over IOR on wo's side);
//   - shading normals: the adjoint of a BSDF evaluated in a shading frame is not symmetric, and
//     the throughput f |cos_s(wi)| becomes f |cos_s(wo)| |cos_g(wi)| / |cos_g(wo)|, so that the
//     light that reaches the camera does not depend on which end the path was traced from.
// Radiance transport goes through this file unchanged (it calls bsdf.h as pt does).
#pragma once
#include "bsdf/bsdf.h"

#define TRANSPORT_RADIANCE 0
#define TRANSPORT_IMPORTANCE 1

// The factor importance transport applies to a radiance-form f |cos_s(wi)| at a vertex with
// geometric normal ng (world wo and wi, their shading-frame z wo_z and wi_z):
// |cos_s(wo)| |cos_g(wi)| / (|cos_g(wo)| |cos_s(wi)|). 0 where wo grazes the geometry (no light
// arrives along it) or wi grazes the shading frame.
inline float shading_normal_correction(float3 wo, float3 wi, float3 ng, float wo_z, float wi_z) {
  float den = fabs(dot(wo, ng)) * fabs(wi_z);
  if (!(den > 0.0f)) return 0.0f;
  float c = fabs(wo_z) * fabs(dot(wi, ng)) / den;
  return isfinite(c) ? c : 0.0f;
}

// eta_rel^2 of a refraction from wo to wi (local; opposite sides) through the BSDF's interface.
inline float transport_eta2(const Bsdf* b, float3 wo, float3 wi) {
  if (!(wo.z * wi.z < 0.0f) || bsdf_is_opaque(b)) return 1.0f;
  float eta = b->eta.x;
  return wo.z > 0.0f ? eta * eta : 1.0f / (eta * eta);
}

// bsdf_eval in `mode` (local directions; the shading-normal factor is the caller's, it needs the
// geometric normal: shading_normal_correction).
inline float3 bsdf_eval_transport(const Bsdf* b, float3 wo, float3 wi, int mode) {
  float3 f = bsdf_eval(b, wo, wi);
  return mode == TRANSPORT_IMPORTANCE ? f * transport_eta2(b, wo, wi) : f;
}

// bsdf_sample in `mode`: a refracted sample's weight loses the radiance scaling in importance
// transport (s->eta: the relative IOR crossed).
inline int bsdf_sample_transport(const Bsdf* b, float3 wo, float3 u, int mode, BsdfSample* s) {
  if (!bsdf_sample(b, wo, u, s)) return 0;
  if (mode == TRANSPORT_IMPORTANCE && s->transmitted) s->weight *= s->eta * s->eta;
  return 1;
}

// Eval with both pdfs in one call: the forward pdf of sampling wi from wo and the reverse pdf of
// sampling wo from wi (what bidirectional MIS needs of each vertex).
inline float3 bsdf_eval_pdf(const Bsdf* b, float3 wo, float3 wi, int mode, float* pdf, float* pdf_rev) {
  *pdf = bsdf_pdf(b, wo, wi);
  *pdf_rev = bsdf_pdf(b, wi, wo);
  return bsdf_eval_transport(b, wo, wi, mode);
}
