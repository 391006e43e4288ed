// Bidirectional MIS by running sums (SmallVCM, src/vertexcm.hxx; Georgiev, "Implementing Vertex
// Connection and Merging", 2012). Each subpath carries dvcm, dvc and dvm: after its vertex i
// they hold the sums over the strategies that could have drawn the subpath's vertices up to i
// from the other end, each as a ratio of pdfs to the pdf of the strategy that did (in the
// heuristic's power), so that a connection's or a merge's weight needs only its two endpoints:
//   w = 1 / (1 + w_light + w_camera).
// Merging enters through two factors (GdrBidirOptions): vm_factor = eta and vc_factor = 1 / eta
// (in the heuristic's power), eta = pi r^2 N the ratio of a merge's density to a connection's, N
// the light subpaths merged with; each is 0 where its technique is off, and the sums then are
// bdpt's.
//
// Conventions of this engine:
//   - Areas are measured with the geometric normal (|ng . w| converts a solid-angle pdf at one
//     vertex into an area pdf at the next), on both subpaths alike.
//   - Russian roulette stays out of the pdfs. Weights are unbiased whenever the strategies of a
//     path sum to one, and the BSDF pdfs alone are a function of the path, whichever end drew it.
//   - The camera strategy's pdf is per pixel area, with one light subpath per pixel and pass, so
//     the count of light subpaths cancels (camera_pdf_dir per unit image area): a heuristic
//     shared by both ends, whatever the pixel filter.
#pragma once
#include "bsdf/bsdf.h"
#include "camera/importance.h"
#include "light/emission.h"
#include "path/emission.h"
#include "path/scene.h"
#include "path/mis.h"
#include "shared/bidir_types.h"

// bdpt's options under the power heuristic: those of the power_* sums (G-BDPT's primal).
inline GdrBidirOptions mis_power_options(void) {
  GdrBidirOptions o;
  o.technique = BIDIR_BDPT;
  o.mis = BIDIR_MIS_POWER;
  o.strategy_s = o.strategy_t = -1;
  o.radius = o.vm_normalization = o.vm_factor = o.vc_factor = 0.0f;
  o.multiplex = o.power_sums = 0;
  return o;
}

// The sums dvcm and dvc of a light subpath leaving the light of emission sample e.
inline void mis_light_start_sums(const SceneData* s, const EmissionSample* e, int mis, float* dvcm, float* dvc) {
  float emission = e->pmf * e->pdf_pos * e->pdf_dir;
  float cos_light = light_is_infinite(s, e->light) ? 1.0f : fabs(dot(e->n, e->dir));
  *dvcm = mis_power_of(emission_direct_pdf(s, e) / emission, mis);
  *dvc = (e->delta_pos || e->delta_dir) ? 0.0f : mis_power_of(cos_light / emission, mis);
}

// A light subpath leaves the light of emission sample e.
inline void mis_light_start(const SceneData* s, const EmissionSample* e, const GdrBidirOptions* o,
                            GdrBidirPathState* st) {
  mis_light_start_sums(s, e, o->mis, &st->dvcm, &st->dvc);
  st->dvm = st->dvc * o->vc_factor;
  st->power_dvcm = st->power_dvc = 0.0f;
  if (o->power_sums) mis_light_start_sums(s, e, BIDIR_MIS_POWER, &st->power_dvcm, &st->power_dvc);
  st->flags = (light_is_infinite(s, e->light) ? BIDIR_PATH_INFINITE : 0) | (o->power_sums ? BIDIR_PATH_POWER_SUMS : 0);
}

// A camera subpath's dvcm as it leaves the camera along a direction at cos_theta to the view axis
// (light tracing's share; dvc starts at 0).
inline float mis_camera_dvcm(const GdrCamera* cam, float cos_theta, int mis) {
  float pdf = camera_pdf_dir(cam, cos_theta);
  return pdf > 0.0f ? mis_power_of(1.0f / pdf, mis) : 0.0f;
}

// A camera subpath leaves the camera along a direction at cos_theta to the view axis.
inline void mis_camera_start(const GdrCamera* cam, float cos_theta, int mis, GdrBidirPathState* st) {
  st->dvcm = mis_camera_dvcm(cam, cos_theta, mis);
  st->dvc = 0.0f;
  st->dvm = 0.0f;
  st->power_dvcm = st->power_dvc = 0.0f;
  st->flags = BIDIR_PATH_ALL_SPECULAR;
}

// The running sums of a subpath reached their next vertex at distance dist, arriving at cos_in to
// the geometric normal (has_length 0: the first segment from a light at infinity). The camera
// paths of the gradient integrators carry the sums beside their own state and call these forms.
inline void mis_sums_arrive(float dist, float cos_in, int has_length, int mis, float* dvcm, float* dvc, float* dvm) {
  if (has_length) *dvcm *= mis_power_of(dist * dist, mis);
  float c = mis_power_of(cos_in, mis);
  *dvcm /= c;
  *dvc /= c;
  *dvm /= c;
}

// The sums scattered in a direction of pdf `pdf` (delta: a delta lobe), leaving at cos_out to the
// geometric normal; pdf_rev: the BSDF's pdf of the way back (the sampled direction to the incoming
// one). A delta lobe cannot be connected to: the sums skip the vertex (its forward and reverse
// lobe choices alike).
inline void mis_sums_scatter(int delta, float pdf, float pdf_rev, float cos_out, const GdrBidirOptions* o,
                             float* dvcm, float* dvc, float* dvm) {
  int mis = o->mis;
  if (delta) {
    *dvcm = 0.0f;
    *dvc *= mis_power_of(cos_out, mis);
    *dvm *= mis_power_of(cos_out, mis);
    return;
  }
  float g = mis_power_of(cos_out / pdf, mis), rev = mis_power_of(pdf_rev, mis);
  *dvc = g * (*dvc * rev + *dvcm + o->vm_factor);
  *dvm = g * (*dvm * rev + *dvcm * o->vc_factor + 1.0f);
  *dvcm = mis_power_of(1.0f / pdf, mis);
}

// bdpt's sums under the power heuristic (power_dvcm, power_dvc: no merging, so no dvm) arrive and
// scatter as above.
inline void mis_power_sums_arrive(float dist, float cos_in, int has_length, float* dvcm, float* dvc) {
  float unused = 0.0f;
  mis_sums_arrive(dist, cos_in, has_length, BIDIR_MIS_POWER, dvcm, dvc, &unused);
}
inline void mis_power_sums_scatter(int delta, float pdf, float pdf_rev, float cos_out, float* dvcm, float* dvc) {
  GdrBidirOptions po = mis_power_options();
  float unused = 0.0f;
  mis_sums_scatter(delta, pdf, pdf_rev, cos_out, &po, dvcm, dvc, &unused);
}

// The subpath reached its next vertex at distance dist, arriving at cos_in to the geometric
// normal (a light subpath's first segment from a light at infinity has no length).
inline void mis_arrive(float dist, float cos_in, int mis, GdrBidirPathState* st) {
  int no_length = st->depth == 0 && (st->flags & BIDIR_PATH_INFINITE);
  mis_sums_arrive(dist, cos_in, !no_length, mis, &st->dvcm, &st->dvc, &st->dvm);
  if (st->flags & BIDIR_PATH_POWER_SUMS) {
    mis_power_sums_arrive(dist, cos_in, !no_length, &st->power_dvcm, &st->power_dvc);
  }
}

// The subpath scattered by BSDF sample bs, leaving at cos_out to the geometric normal; pdf_rev:
// the BSDF's pdf of the way back.
inline void mis_scatter(const BsdfSample* bs, float pdf_rev, float cos_out, const GdrBidirOptions* o,
                        GdrBidirPathState* st) {
  if (!bs->delta) st->flags &= ~BIDIR_PATH_ALL_SPECULAR;
  mis_sums_scatter(bs->delta, bs->pdf, pdf_rev, cos_out, o, &st->dvcm, &st->dvc, &st->dvm);
  if (st->flags & BIDIR_PATH_POWER_SUMS) {
    mis_power_sums_scatter(bs->delta, bs->pdf, pdf_rev, cos_out, &st->power_dvcm, &st->power_dvc);
  }
}

// What the sums say of the strategies on one side of a connection: the pdf with which the other
// side's vertex would have drawn this vertex (area, pdf_area), and this vertex's BSDF pdf back
// toward its own subpath given the connection's direction (pdf_rev).
inline float mis_side(float pdf_area, float dvcm, float dvc, float pdf_rev, const GdrBidirOptions* o) {
  return mis_power_of(pdf_area, o->mis) * (o->vm_factor + dvcm + dvc * mis_power_of(pdf_rev, o->mis));
}

// What the sums say of the strategies on one side of a merge: the connections that could have
// drawn the subpath (dvcm), and the merges at its other vertices, with the BSDF pdf at the merge
// point toward this side's subpath (pdf).
inline float mis_merge_side(float dvcm, float dvm, float pdf, const GdrBidirOptions* o) {
  return dvcm * o->vc_factor + dvm * mis_power_of(pdf, o->mis);
}

// 1 / (1 + others), 0 where a degenerate pdf made the sum meaningless.
inline float mis_weight(float others) {
  float w = 1.0f / (1.0f + others);
  return isfinite(others) && w > 0.0f ? w : 0.0f;
}

// The camera subpath (depth >= 1 scatterings, sums dvcm and dvc) found emission whose light point
// has direct pdf `direct` and emission pdf `emission` toward the subpath: the other strategies'
// share, relative to this one's.
inline float mis_emission_others(float direct, float emission, float dvcm, float dvc, int mis) {
  return mis_power_of(direct, mis) * dvcm + mis_power_of(emission, mis) * dvc;
}

// The emission pdfs of a camera subpath's vertex su, seen along wo (toward the subpath), as the
// light-point (s = 1) and light-subpath (s >= 2) strategies would draw it: the other strategies'
// share for the sums dvcm, dvc.
inline float mis_surface_emission_others(const SceneData* s, const Surface* su, float3 wo, float dvcm, float dvc,
                                         int mis) {
  if (su->light < 0) return 0.0f;
  float direct = light_pmf(s, su->light) * light_emission_pdf_pos(s, su->light, su->area);
  float emission = direct * light_emission_over_direct(s, su->light, su->ng, wo);
  return mis_emission_others(direct, emission, dvcm, dvc, mis);
}

// The same for a camera subpath that escaped along dir into the environment.
inline float mis_escaped_emission_others(const SceneData* s, float3 dir, float dvcm, float dvc, int mis) {
  if (s->env_light < 0) return 0.0f;
  float direct = escaped_light_pdf(s, dir);
  float emission = direct * light_emission_over_direct(s, s->env_light, (float3)(0.0f), -dir);
  return mis_emission_others(direct, emission, dvcm, dvc, mis);
}

// A camera vertex (surface normal ng, BSDF b, local directions wo_l toward its subpath and wi_l
// toward the light point of sample ls from light `light`) connected to that light point (s = 1):
// the other strategies' share, from the camera subpath's sums dvcm and dvc.
inline float mis_light_point_others(const SceneData* s, const Bsdf* b, float3 wo_l, float3 wi_l, float3 ng, int light,
                                    const LightSample* ls, float dvcm, float dvc, const GdrBidirOptions* o) {
  float pdf_fwd = bsdf_pdf(b, wo_l, wi_l), pdf_rev = bsdf_pdf(b, wi_l, wo_l);
  float cos_z = fabs(dot(ng, ls->wi));
  float w_light = ls->delta ? 0.0f : mis_power_of(pdf_fwd / ls->pdf, o->mis);
  float pdf_emit = light_emission_over_direct(s, light, ls->light_normal, -ls->wi) * cos_z;
  if (!light_is_infinite(s, light)) pdf_emit /= ls->dist * ls->dist;
  float w_camera = mis_side(pdf_emit, dvcm, dvc, pdf_rev, o);
  return w_light + w_camera;
}

// The techniques a render combines: connections (bdpt, vcm; lt's camera connections are its
// only strategy) and merging (pm, vcm).
inline int bidir_connects(const GdrBidirOptions* o) { return o->technique == BIDIR_BDPT || o->technique == BIDIR_VCM; }
inline int bidir_merges(const GdrBidirOptions* o) { return o->technique == BIDIR_PM || o->technique == BIDIR_VCM; }

// A weight of the strategy (s, t): w under MIS, 1 where a single strategy is shown.
inline float bidir_weight(const GdrBidirOptions* o, float w) { return o->strategy_s < 0 ? w : 1.0f; }
