// The path stages of a material queue's lane kernel (pt/shade_lanes.h) on eight lanes: a
// vertex's frame and BSDF, next-event estimation's light sample and the BSDF toward it
// (path/nee.h), and continuation by BSDF sampling with Russian roulette (path/continuation.h,
// radiance transport), each its scalar stage's arithmetic from the same random numbers.
#pragma once
#include "bsdf/bsdf_lanes.h"
#include "core/lanes.h"
#include "light/light_lanes.h"

// The lanes' vertices, all of one BSDF type.
typedef struct {
  int type;  // BSDF_*
  BsdfLanes b;
  FrameLanes frame;
  Lanes3 ng;         // geometric normals (world)
  Lanes3 wo_n;       // toward the previous vertices, in the frames, unit, as bsdf_flip_side turns it
  float8 flip_sign;  // -1 where a two-sided surface is seen from below (bsdf_flip_side)
} VertexLanes;

inline VertexLanes vertex_lanes(int type, const BsdfLaneArrays* bsdf, const LaneArray3* ns, const LaneArray3* ng,
                                const LaneArray3* wo) {
  VertexLanes v;
  v.type = type;
  v.b = bsdf_lanes_load(bsdf);
  v.frame = frame_lanes_from_normal(lanes3_load(ns));
  v.ng = lanes3_load(ng);
  Lanes3 wo_local = frame_lanes_to_local(&v.frame, lanes3_load(wo));
  v.flip_sign = select((float8)(1.0f), (float8)(-1.0f), v.b.twosided & (wo_local.z < 0.0f));
  v.wo_n = lanes3_normalize_or_zero(wo_local);
  v.wo_n.z *= v.flip_sign;
  return v;
}

// nee_sample for the lanes k with want[k], from their light blocks ul, seen from p: the samples
// *ls, the BSDF's value *f and pdf *bsdf_pdf toward them. Returns the lanes whose sample is usable
// (drawn, and the normals agree on its side).
inline int8 nee_lanes(const SceneData* s, const VertexLanes* v, const int* want, RngBlockLanes ul, const LaneArray3* p,
                      LightSampleLanes* ls, Lanes3* f, float8* bsdf_pdf) {
  light_sample_lanes(s, want, ul.x, ul.y, ul.z, p, ls);
  Lanes3 wi = lanes3_load(&ls->wi);
  Lanes3 wi_local = frame_lanes_to_local(&v->frame, wi);
  int8 usable = (vload8(0, ls->ok) != 0) & (lanes3_dot(wi, v->ng) * wi_local.z > 0.0f);
  Lanes3 wi_n = lanes3_normalize_or_zero(wi_local);
  wi_n.z *= v->flip_sign;
  *f = bsdf_lanes_eval(v->type, &v->b, v->wo_n, wi_n, bsdf_pdf);
  return usable;
}

// path_continue for the lanes `depth` bounces into their paths, from their BSDF blocks ub: the
// sample, its side test, and roulette after rr_depth bounces. *beta becomes the continuation's
// throughput; *wi (world), *pdf and *delta are the sample's. *nonfinite: the lanes whose
// throughput overflowed. Returns the lanes that continue.
inline int8 continue_lanes(const VertexLanes* v, RngBlockLanes ub, int8 depth, int rr_depth, Lanes3* beta, Lanes3* wi,
                           float8* pdf, int8* delta, int8* nonfinite) {
  Lanes3 wi_s, weight;
  int8 sample_ok = bsdf_lanes_sample(v->type, &v->b, v->wo_n, ub.x, ub.y, ub.z, &wi_s, &weight, pdf, delta);
  wi_s.z *= v->flip_sign;
  *wi = frame_lanes_to_world(&v->frame, wi_s);
  sample_ok &= lanes3_dot(*wi, v->ng) * wi_s.z > 0.0f;
  Lanes3 t = lanes3_mul(*beta, weight);
  int8 t_finite = lanes3_finite(t);
  float8 t_max = lanes3_max(t);
  int8 roulette = depth + 1 >= rr_depth;
  float8 rr = fmin(t_max, 0.95f);  // the survival probability where roulette applies
  *nonfinite = sample_ok & ~t_finite;
  t.x = select(t.x, t.x / rr, roulette);
  t.y = select(t.y, t.y / rr, roulette);
  t.z = select(t.z, t.z / rr, roulette);
  *beta = t;
  return sample_ok & t_finite & (t_max > 0.0f) & (~roulette | (ub.w < rr));
}
