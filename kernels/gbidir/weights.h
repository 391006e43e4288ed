// G-BDPT's MIS (Manzi et al. 2015, "Gradient-Domain Bidirectional Path Tracing"): a strategy st of
// base path x and its offset y = T(x) share one weight, the balance heuristic over the shifted
// strategies (all but light tracing, below) of both paths,
//   w_st(x) = p_st(x) / sum_k [p_k(x) + p_k(y) |J|] = 1 / (A + R B),
// with A = sum_k p_k(x) / p_st(x) (1 + the bidirectional sums' "others" of x), B the same of y,
// and R = p_st(y) |J| / p_st(x): the shifted camera prefix's pdf ratio (the light subpath is the
// same for both). Both f(x) and f(y) |J| are weighted by it. A shift that fails leaves the base
// its bidirectional weight 1 / A.
//
// Light tracing (t = 1) is shifted on its own (gbidir/light_tracing.h): its share of every path,
// bdpt's weight over every strategy w_lt(z) = p_lt(z) / sum_k p_k(z), is a layer of the image
// whose base and offset split by their pair's weight. The shifted strategies here share the rest
// of each path: their sums A and B leave light tracing out, and the weights of x and of y are
// scaled by 1 - w_lt of their own path, (1 + others) / (1 + others with light tracing)
// (gbdpt_shifted_share). For every path the weights of its base events, its offset events and its
// light tracing then sum to 1.
//
// G-BDPT's primal is the pairs' mean, as G-PT's, unless --primal power (GDR_GBDPT_POWER_PRIMAL)
// makes it bdpt's estimate of the base paths alone, weighed by the power heuristic over every
// strategy as Manzi et al.'s reference code does (the balance heuristic for the gradients only),
// from the power_* sums of both subpaths: w = 1 / (1 + others under the power heuristic). That
// primal holds the emission seen directly too, and light tracing's share of each path (the splat's
// `primal` weight).
//
// G-VCM (Sun et al. 2017) weighs the same way over VCM's strategies: the sums carry merging's
// factors (the pass's, in GdrGptParams), and a merge's share of base and offset comes from the
// same heuristic (gbidir/merge.h).
#pragma once
#include "bidir/connection.h"
#include "bidir/subpath_mis.h"
#include "shared/gbidir_types.h"
#include "shared/gpt_types.h"

// The options the camera subpaths' sums and weights take: the balance heuristic, and merging's
// factors where G-VCM merges.
inline GdrBidirOptions gbdpt_options(const GdrGptParams* p) {
  GdrBidirOptions o;
  o.technique = p->vm_factor > 0.0f ? BIDIR_VCM : BIDIR_BDPT;
  o.mis = BIDIR_MIS_BALANCE;
  o.strategy_s = o.strategy_t = -1;
  o.radius = o.vm_normalization = 0.0f;
  o.vm_factor = p->vm_factor;
  o.vc_factor = p->vc_factor;
  o.multiplex = o.power_sums = 0;
  return o;
}

// others_x, others_y: the two paths' bidirectional "others" for the strategy, light tracing left
// out; r: R; formed: the offset exists (else the base's weight alone).
inline float gbdpt_weight(float others_x, float others_y, float r, int formed) {
  float d = 1.0f + others_x + (formed ? r * (1.0f + others_y) : 0.0f);
  float w = 1.0f / d;
  return isfinite(d) && w > 0.0f ? w : 0.0f;
}

// 1 - w_lt of a path whose strategy has `others` without light tracing and `all_others` with it.
inline float gbdpt_shifted_share(float others, float all_others) {
  float share = (1.0f + others) / (1.0f + all_others);
  return isfinite(share) && share > 0.0f ? fmin(share, 1.0f) : 0.0f;
}

// The weights of base and offset for a strategy whose "others" are ox of the base and oy of the
// offset (x: light tracing left out, y: with it).
inline float2 gbdpt_pair_weights(float2 ox, float2 oy, float r, int formed) {
  float w = gbdpt_weight(ox.x, oy.x, r, formed);
  return (float2)(w * gbdpt_shifted_share(ox.x, ox.y), w * gbdpt_shifted_share(oy.x, oy.y));
}

// The "others" of the strategies a camera subpath with sums m evaluates itself (bidir/subpath_mis.h):
// emission found at a surface (s = 0), in the environment, and a light point connected (s = 1).
inline float2 gbdpt_surface_emission_others(const SceneData* s, const Surface* su, float3 wo, const GbdptSums* m) {
  return (float2)(mis_surface_emission_others(s, su, wo, m->dvcm, m->dvc, BIDIR_MIS_BALANCE),
                  mis_surface_emission_others(s, su, wo, m->all_dvcm, m->all_dvc, BIDIR_MIS_BALANCE));
}
inline float2 gbdpt_escaped_emission_others(const SceneData* s, float3 dir, const GbdptSums* m) {
  return (float2)(mis_escaped_emission_others(s, dir, m->dvcm, m->dvc, BIDIR_MIS_BALANCE),
                  mis_escaped_emission_others(s, dir, m->all_dvcm, m->all_dvc, BIDIR_MIS_BALANCE));
}
inline float2 gbdpt_light_point_others(const SceneData* s, const Bsdf* b, float3 wo_l, float3 wi_l, float3 ng,
                                       int light, const LightSample* ls, const GbdptSums* m,
                                       const GdrBidirOptions* o) {
  return (float2)(mis_light_point_others(s, b, wo_l, wi_l, ng, light, ls, m->dvcm, m->dvc, o),
                  mis_light_point_others(s, b, wo_l, wi_l, ng, light, ls, m->all_dvcm, m->all_dvc, o));
}

// The "others" of connection c with light tracing's share, from the camera vertex's sums with it.
inline float gbdpt_connection_all_others(const BidirConnection* c, float all_dvcm, float all_dvc,
                                         const GdrBidirOptions* o) {
  return c->w_light + bidir_connection_camera_side(c, all_dvcm, all_dvc, o);
}

// The sums of a camera subpath leaving the camera along a direction at cos_theta to its axis.
inline GbdptSums gbdpt_sums_start(const GdrCamera* cam, float cos_theta) {
  GbdptSums m;
  m.dvcm = m.dvc = m.dvm = m.all_dvc = m.all_dvm = m.power_dvcm = m.power_dvc = 0.0f;
  m.all_dvcm = mis_camera_dvcm(cam, cos_theta, BIDIR_MIS_BALANCE);
#if defined(GDR_GBDPT_POWER_PRIMAL)
  m.power_dvcm = mis_camera_dvcm(cam, cos_theta, BIDIR_MIS_POWER);
#endif
  return m;
}

// The camera subpath's sums reach its next vertex (dist away, arriving at cos_in) and scatter
// there (pdf of the direction taken, delta lobe or not, pdf_rev back, leaving at cos_out).
inline void gbdpt_sums_arrive(float dist, float cos_in, GbdptSums* m) {
  mis_sums_arrive(dist, cos_in, 1, BIDIR_MIS_BALANCE, &m->dvcm, &m->dvc, &m->dvm);
  mis_sums_arrive(dist, cos_in, 1, BIDIR_MIS_BALANCE, &m->all_dvcm, &m->all_dvc, &m->all_dvm);
#if defined(GDR_GBDPT_POWER_PRIMAL)
  mis_power_sums_arrive(dist, cos_in, 1, &m->power_dvcm, &m->power_dvc);
#endif
}
inline void gbdpt_sums_scatter(int delta, float pdf, float pdf_rev, float cos_out, const GdrBidirOptions* o,
                               GbdptSums* m) {
  mis_sums_scatter(delta, pdf, pdf_rev, cos_out, o, &m->dvcm, &m->dvc, &m->dvm);
  mis_sums_scatter(delta, pdf, pdf_rev, cos_out, o, &m->all_dvcm, &m->all_dvc, &m->all_dvm);
#if defined(GDR_GBDPT_POWER_PRIMAL)
  mis_power_sums_scatter(delta, pdf, pdf_rev, cos_out, &m->power_dvcm, &m->power_dvc);
#endif
}

// The primal's weights of the strategies a camera subpath with sums m evaluates itself (as
// gbdpt_*_others above), and of a connection c between light vertex y and camera vertex z.
inline float gbdpt_primal_surface_emission(const SceneData* s, const Surface* su, float3 wo, const GbdptSums* m) {
  return mis_weight(mis_surface_emission_others(s, su, wo, m->power_dvcm, m->power_dvc, BIDIR_MIS_POWER));
}
inline float gbdpt_primal_escaped_emission(const SceneData* s, float3 dir, const GbdptSums* m) {
  return mis_weight(mis_escaped_emission_others(s, dir, m->power_dvcm, m->power_dvc, BIDIR_MIS_POWER));
}
inline float gbdpt_primal_light_point(const SceneData* s, const Bsdf* b, float3 wo_l, float3 wi_l, float3 ng,
                                      int light, const LightSample* ls, const GbdptSums* m) {
  GdrBidirOptions po = mis_power_options();
  return mis_weight(mis_light_point_others(s, b, wo_l, wi_l, ng, light, ls, m->power_dvcm, m->power_dvc, &po));
}
inline float gbdpt_primal_connection(const BidirConnection* c, const GdrBidirVertex* y, const GdrBidirVertex* z) {
  GdrBidirOptions po = mis_power_options();
  return mis_weight(bidir_connection_light_side(c, y->power_dvcm, y->power_dvc, &po) +
                    bidir_connection_camera_side(c, z->power_dvcm, z->power_dvc, &po));
}
