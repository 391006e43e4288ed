// G-BDPT's MIS (Manzi et al. 2015, "Gradient-Domain Bidirectional Path Tracing"): a strategy st of
// base path x and its offset y = T(x) share one weight, the balance heuristic over every strategy
// of both paths,
//   w_st(x) = p_st(x) / sum_k [p_k(x) + p_k(y) |J|] = 1 / (A + R B),
// with A = sum_k p_k(x) / p_st(x) (1 + the bidirectional sums' "others" of x), B the same of y,
// and R = p_st(y) |J| / p_st(x): the shifted camera prefix's pdf ratio (the light subpath is the
// same for both). Both f(x) and f(y) |J| are weighted by it. A shift that fails leaves the base
// its bidirectional weight 1 / A.
//
// gbdpt leaves light tracing (t = 1) out of its strategies: its camera subpaths start with no
// share for it (dvcm = 0), and its light subpaths do not connect to the camera.
#pragma once
#include "bidir/subpath_mis.h"
#include "shared/gbidir_types.h"
#include "shared/gpt_types.h"

inline GdrBidirOptions gbdpt_options(void) {
  GdrBidirOptions o;
  o.technique = BIDIR_BDPT;
  o.mis = BIDIR_MIS_BALANCE;
  o.strategy_s = o.strategy_t = -1;
  o.radius = o.vm_normalization = o.vm_factor = o.vc_factor = 0.0f;
  o.multiplex = 0;
  o.no_camera_connections = 1;
  return o;
}

// others_x, others_y: the two paths' bidirectional "others" for the strategy; r: R; formed: the
// offset exists (else the base's weight alone).
inline float gbdpt_weight(float others_x, float others_y, float r, int formed) {
  float d = 1.0f + others_x + (formed ? r * (1.0f + others_y) : 0.0f);
  float w = 1.0f / d;
  return isfinite(d) && w > 0.0f ? w : 0.0f;
}

// The camera subpath's sums reach its next vertex (dist away, arriving at cos_in) and scatter
// there (pdf of the direction taken, delta lobe or not, pdf_rev back, leaving at cos_out).
inline void gbdpt_sums_arrive(float dist, float cos_in, float* dvcm, float* dvc) {
  float dvm = 0.0f;
  mis_sums_arrive(dist, cos_in, 1, BIDIR_MIS_BALANCE, dvcm, dvc, &dvm);
}
inline void gbdpt_sums_scatter(int delta, float pdf, float pdf_rev, float cos_out, float* dvcm, float* dvc) {
  GdrBidirOptions o = gbdpt_options();
  float dvm = 0.0f;
  mis_sums_scatter(delta, pdf, pdf_rev, cos_out, &o, dvcm, dvc, &dvm);
}

// Whether a camera vertex of `depth` scatterings before it can still connect to a light
// subpath's vertex (one more segment each side at least; max_depth in segments, < 0: unbounded).
inline int gbdpt_connects_at(int depth, int max_depth) { return max_depth < 0 || depth + 3 <= max_depth; }
