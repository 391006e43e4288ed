// Shift mappings of the gradient-domain path tracer, one vertex at a time, with their Jacobians
// (Lehtinen et al. 2013, Kettunen et al. 2015). All directions are unit vectors pointing away
// from the vertex; wo toward the previous vertex, wi toward the next. Local-frame functions take
// directions in the vertex's shading frame.
#pragma once
#include "bsdf/bsdf.h"

// Half-vector copy: the base scattered wo -> wi about half vector h (reflection, or refraction
// with relative IOR eta_rel = IOR on wi's side / IOR on wo's side); the offset, arriving from
// wo_off at a surface of relative IOR eta_material (int / ext), scatters about the same local h.
// Returns 0 where the offset cannot follow (total internal reflection in the offset only, or
// the offset direction leaves on the other side than the base's). *jacobian = |d wi_off / d wi|.
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

// Reconnection: the base went x -> z, the offset goes y -> z (z fixed, with normal nz). The
// solid-angle Jacobian |d w_y / d w_x| = (cos_y' / d_y^2) / (cos_x / d_x^2), with the cosines at z
// toward y and toward x.
inline float reconnect_jacobian(float3 x, float3 y, float3 z, float3 nz) {
  float3 dx = x - z, dy = y - z;
  float lx2 = dot(dx, dx), ly2 = dot(dy, dy);
  if (!(lx2 > 0.0f) || !(ly2 > 0.0f)) return 0.0f;
  float cx = fabs(dot(dx, nz)) * rsqrt(lx2);
  float cy = fabs(dot(dy, nz)) * rsqrt(ly2);
  return safe_div(cy * lx2, cx * ly2);
}

// The offset's sample of the same delta lobe the base took (reflection or transmission),
// without random choice: the lobe is selected by u.x, so both ends of its range are tried.
// Returns 0 when the offset's BSDF has no such lobe here (e.g. total internal reflection).
inline int bsdf_sample_delta_lobe(const Bsdf* b, float3 wo, int transmitted, BsdfSample* s) {
  const float ends[2] = {0.0f, 0x1.fffffep-1f};
  for (int i = 0; i < 2; ++i) {
    if (bsdf_sample(b, wo, (float3)(ends[i], 0.5f, 0.5f), s) && s->delta && s->transmitted == transmitted) {
      return 1;
    }
  }
  return 0;
}

// Balance-heuristic weight of the base's sample among four techniques: the base's own two (the
// sampled one with pdf p, the other with pdf q) and the offset's two (p_off, q_off) scaled by the
// offset's prefix ratio r = p(y)|J| / p(x) (Kettunen et al. 2015, eq. 7 with next-event
// estimation). A dead offset has r = 0 and leaves the plain path-tracing MIS weight.
inline float gpt_weight(float p, float q, float r, float p_off, float q_off) {
  float denom = p + q + r * (p_off + q_off);
  return denom > 0.0f && isfinite(denom) ? p / denom : 0.0f;
}
