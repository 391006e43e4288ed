// The BSDFs that lane kernels shade (kernels/pt/shade_lanes.h), eight lanes at once: diffuse and
// smooth plastic. Each helper is its scalar namesake's arithmetic lane by lane (diffuse.h,
// plastic.h, fresnel.h, and bsdf.h's checks around them); `type` is a constant of the calling
// kernel, so each kernel keeps only its own type's branch. Directions are local, unit, and
// already on the upper side (bsdf_flip_side applied).
#pragma once
#include "bsdf/bsdf_types.h"
#include "bsdf/fresnel.h"
#include "bsdf/plastic.h"
#include "core/lanes.h"
#include "shared/scene_types.h"

// What the lane steps read of each lane's Bsdf, set lane by lane. A plastic's diffuse term is
// plastic_base (its internal scattering folded in), which the lane steps take as it is.
typedef struct {
  LaneArray3 diffuse, specular;
  float eta[LANES], specular_weight[LANES];
  int twosided[LANES];
} BsdfLaneArrays;

typedef struct {
  Lanes3 diffuse, specular;
  float8 eta, specular_weight;
  int8 twosided;  // a mask: both types are opaque, so bsdf_flip_side is twosided && wo.z < 0
} BsdfLanes;

// Harmless values for a lane without a hit.
inline void bsdf_lanes_clear(BsdfLaneArrays* a, int k) {
  lane_array3_set(&a->diffuse, k, (float3)(0.0f));
  lane_array3_set(&a->specular, k, (float3)(0.0f));
  a->eta[k] = 1.5f;
  a->specular_weight[k] = 0.5f;
  a->twosided[k] = 0;
}

inline void bsdf_lanes_set(BsdfLaneArrays* a, int k, const Bsdf* b) {
  lane_array3_set(&a->diffuse, k, b->type == BSDF_PLASTIC ? plastic_base(b) : b->diffuse);
  lane_array3_set(&a->specular, k, b->specular_r);
  a->eta[k] = b->eta.x;
  a->specular_weight[k] = b->specular_weight;
  a->twosided[k] = b->twosided ? -1 : 0;
}

inline BsdfLanes bsdf_lanes_load(const BsdfLaneArrays* a) {
  BsdfLanes b = {lanes3_load(&a->diffuse), lanes3_load(&a->specular), vload8(0, a->eta),
                 vload8(0, a->specular_weight), vload8(0, a->twosided)};
  return b;
}

FRESNEL_DIELECTRIC(fresnel_dielectric_lanes, fresnel_dielectric_r_lanes, float8, int8)
PLASTIC_SPECULAR_PROBABILITY(plastic_lobe_probability_lanes, float8)

// bsdf_eval (f |cos wi|) and, in *pdf, bsdf_pdf of wo and wi.
inline Lanes3 bsdf_lanes_eval(int type, const BsdfLanes* b, Lanes3 wo, Lanes3 wi, float8* pdf) {
  int8 upper = (wo.z > 0.0f) & (wi.z > 0.0f);
  float8 cos_pdf = fmax(wi.z, 0.0f) * M_1_PI_F;  // square_to_cosine_hemisphere_pdf
  Lanes3 f = lanes3_scale(b->diffuse, cos_pdf);
  float8 p = cos_pdf;
  if (type == BSDF_PLASTIC) {
    float8 r_o = fresnel_dielectric_r_lanes(wo.z, b->eta);
    float8 t_i = 1.0f - fresnel_dielectric_r_lanes(wi.z, b->eta);
    f = lanes3_finite_or_zero(lanes3_scale(b->diffuse, cos_pdf * (1.0f - r_o) * t_i / (b->eta * b->eta)));
    p = (1.0f - plastic_lobe_probability_lanes(r_o, b->specular_weight)) * cos_pdf;
  }
  *pdf = fmax(select((float8)(0.0f), p, upper & isfinite(p)), 0.0f);
  Lanes3 zero = {(float8)(0.0f), (float8)(0.0f), (float8)(0.0f)};
  return lanes3_fmax0(lanes3_finite_or_zero(lanes3_select(zero, f, upper)));
}

// bsdf_sample from (u0, u1, u2): the lanes that have a sample (its checks included), with its wi,
// weight, pdf and whether it took a delta lobe.
inline int8 bsdf_lanes_sample(int type, const BsdfLanes* b, Lanes3 wo, float8 u0, float8 u1, float8 u2, Lanes3* wi,
                              Lanes3* weight, float8* pdf, int8* delta) {
  Lanes3 c = square_to_cosine_hemisphere_lanes(u1, u2);
  float8 cos_pdf = fmax(c.z, 0.0f) * M_1_PI_F;
  int8 ok = (wo.z > 0.0f) & (c.z > 0.0f);
  *wi = c;
  *pdf = cos_pdf;
  *weight = b->diffuse;
  *delta = (int8)(0);
  if (type == BSDF_PLASTIC) {
    float8 r_o = fresnel_dielectric_r_lanes(wo.z, b->eta);
    float8 ps = plastic_lobe_probability_lanes(r_o, b->specular_weight);
    int8 specular = u0 < ps;
    float8 t_i = 1.0f - fresnel_dielectric_r_lanes(c.z, b->eta);
    Lanes3 diffuse = lanes3_finite_or_zero(
        lanes3_scale(b->diffuse, (1.0f - r_o) * t_i / (b->eta * b->eta * (1.0f - ps))));
    Lanes3 mirror = {-wo.x, -wo.y, wo.z};  // reflect_local
    *wi = lanes3_select(c, mirror, specular);
    *pdf = select((1.0f - ps) * cos_pdf, ps, specular);
    *weight = lanes3_select(diffuse, lanes3_scale(b->specular, r_o / ps), specular);
    *delta = specular;
    ok = (wo.z > 0.0f) & (specular | ((c.z > 0.0f) & (*pdf > 0.0f)));
  }
  ok &= lanes3_finite(*weight) & (*pdf > 0.0f) & isfinite(*pdf);
  *weight = lanes3_fmax0(*weight);
  return ok & (lanes3_max(*weight) > 0.0f);
}
