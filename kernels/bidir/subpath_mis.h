// Bidirectional MIS by running sums (SmallVCM, src/vertexcm.hxx; Georgiev, "Implementing Vertex
// Connection and Merging", 2012). Each subpath carries dvcm and dvc: after its vertex i they
// hold the sums over the strategies that could have drawn the subpath's vertices up to i from
// the other end, each as a ratio of pdfs to the pdf of the strategy that did (in the heuristic's
// power), so that a connection's weight needs only its two endpoints:
//   w = 1 / (1 + w_light + w_camera).
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
#include "path/mis.h"
#include "shared/bidir_types.h"

// A light subpath leaves the light of emission sample e.
inline void mis_light_start(const SceneData* s, const EmissionSample* e, int mis, GdrBidirPathState* st) {
  float emission = e->pmf * e->pdf_pos * e->pdf_dir;
  int infinite = light_is_infinite(s, e->light);
  st->dvcm = mis_power_of(emission_direct_pdf(s, e) / emission, mis);
  float cos_light = infinite ? 1.0f : fabs(dot(e->n, e->dir));
  st->dvc = (e->delta_pos || e->delta_dir) ? 0.0f : mis_power_of(cos_light / emission, mis);
  st->flags = infinite ? BIDIR_PATH_INFINITE : 0;
}

// A camera subpath leaves the camera along a direction at cos_theta to the view axis.
inline void mis_camera_start(const GdrCamera* cam, float cos_theta, int mis, GdrBidirPathState* st) {
  float pdf = camera_pdf_dir(cam, cos_theta);
  st->dvcm = pdf > 0.0f ? mis_power_of(1.0f / pdf, mis) : 0.0f;
  st->dvc = 0.0f;
  st->flags = 0;
}

// The subpath reached its next vertex at distance dist, arriving at cos_in to the geometric
// normal (a light subpath's first segment from a light at infinity has no length).
inline void mis_arrive(float dist, float cos_in, int mis, GdrBidirPathState* st) {
  int no_length = st->depth == 0 && (st->flags & BIDIR_PATH_INFINITE);
  if (!no_length) st->dvcm *= mis_power_of(dist * dist, mis);
  float c = mis_power_of(cos_in, mis);
  st->dvcm /= c;
  st->dvc /= c;
}

// The subpath scattered by BSDF sample bs, leaving at cos_out to the geometric normal; pdf_rev:
// the BSDF's pdf of the way back (the sampled direction to the incoming one). A delta lobe
// cannot be connected to: the sums skip the vertex (its forward and reverse lobe choices alike).
inline void mis_scatter(const BsdfSample* bs, float pdf_rev, float cos_out, int mis, GdrBidirPathState* st) {
  if (bs->delta) {
    st->dvcm = 0.0f;
    st->dvc *= mis_power_of(cos_out, mis);
    return;
  }
  st->dvc = mis_power_of(cos_out / bs->pdf, mis) * (st->dvc * mis_power_of(pdf_rev, mis) + st->dvcm);
  st->dvcm = mis_power_of(1.0f / bs->pdf, mis);
}

// What the sums say of the strategies on one side of a connection: the pdf with which the other
// side's vertex would have drawn this vertex (area, pdf_area), and this vertex's BSDF pdf back
// toward its own subpath given the connection's direction (pdf_rev).
inline float mis_side(float pdf_area, float dvcm, float dvc, float pdf_rev, int mis) {
  return mis_power_of(pdf_area, mis) * (dvcm + dvc * mis_power_of(pdf_rev, mis));
}

// 1 / (1 + others), 0 where a degenerate pdf made the sum meaningless.
inline float mis_weight(float others) {
  float w = 1.0f / (1.0f + others);
  return isfinite(others) && w > 0.0f ? w : 0.0f;
}

// The camera subpath (depth >= 1 scatterings) found emission whose light point has direct pdf
// `direct` and emission pdf `emission` toward the subpath.
inline float mis_emission_weight(float direct, float emission, const GdrBidirPathState* st, int mis) {
  return mis_weight(mis_power_of(direct, mis) * st->dvcm + mis_power_of(emission, mis) * st->dvc);
}

// The strategy (s light vertices, t camera vertices) is the one shown, or all are.
inline int bidir_strategy_shown(const GdrBidirOptions* o, int s, int t) {
  return o->strategy_s < 0 || (o->strategy_s == s && o->strategy_t == t);
}

// A weight of the strategy (s, t): w under MIS, 1 where a single strategy is shown.
inline float bidir_weight(const GdrBidirOptions* o, float w) { return o->strategy_s < 0 ? w : 1.0f; }
