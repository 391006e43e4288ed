// G-PM's manifold photon shift (Hua et al. 2017, the reference's shiftPhotonManifold): a photon y
// whose parent is a delta vertex arrived through a chain s_1 .. s_m of delta vertices from the last
// rough vertex b of its light subpath (a stored vertex, or the point it left an area light from).
// The offset photon y' is the first surface the ray from s_m toward the photon's target
// (photon_shift_target) meets; a manifold walk (manifold/walk.h, run by the host's manifold stage)
// then moves the chain so that it joins y' to b, b fixed: the walk's x_0 is y' (from the base's
// y), its x_e is b, its vertices the chain from the photon's side. The offset's throughput and
// density change by the parent's F and pdf toward the new chain (photon_parent_eval), each delta
// vertex's lobe value and probability (with importance transport's shading-normal factor), and
// the generalized geometry term |d w_b / dA(y)| from b to the photon, which the walk gives seen
// from its fixed end x_e = b (g_walk_at_end; the term seen from the photon, turned around by the
// end cosines, is off by up to several percent where interpolated normals bend the chain: tests/
// gbidir/test_photon_shift.cpp). The photon's move onto its own surface counts 1,
// as for the reconnection (gbidir/photon_shift.h). The walk itself checks that it leads back to
// the base chain; the merge stage also checks that the new chain's last vertex sees the base
// photon (the reverse shift's ray: gbidir/merge.h). Built where gpm or gvcm walks (GDR_MANIFOLD).
#pragma once
#include "bsdf/transport.h"
#include "gbidir/photon_shift.h"
#include "manifold/walk.h"
#include "shared/gpt_types.h"
#include "shift/delta_lobe.h"

#define GPM_NO_WALK 0xffffffffu  // a shift that took no walk

typedef struct PhotonChain {
  int count;                                // m
  GdrManifoldPoint end;                     // b
  GdrManifoldPoint v[MANIFOLD_MAX_CHAIN];   // s_1 .. s_m, from b's side
  PhotonParent parent;                      // b, as photon_parent_eval reads it
} PhotonChain;

// The chain before store entry `entry` (vertex j of subpath `slot`), photon y, whose parent is a
// delta vertex: 1, or 0 with *reason the GPT_COUNTER_FAIL_* it fails by (a chain longer than
// MANIFOLD_MAX_CHAIN; a light other than an area light before it, or no points kept).
inline int photon_chain(const SceneData* s, __global const GdrBidirVertex* store,
                        __global const GdrLightOrigin* origins, __global const GdrManifoldPoint* delta_points,
                        uint delta_depths, uint stride, uint entry, const GdrBidirVertex* y, PhotonChain* ch,
                        int* reason) {
  uint j = entry / stride, slot = entry % stride;
  *reason = GPT_COUNTER_FAIL_PHOTON_PARENT;
  int first;  // the chain's first vertex, in bounces from the light
  if (j > 0) {
    GdrBidirVertex q = store[(j - 1) * stride + slot];
    first = q.depth + 1;
    ch->parent = photon_parent_vertex(s, &q);
    GdrManifoldPoint b = {q.prim, q.u, q.v};
    ch->end = b;
  } else {
    GdrLightOrigin o = origins[slot];
    if (o.light < 0 || s->lights[o.light].type != LIGHT_AREA) return 0;
    first = 1;
    ch->parent = photon_parent_light(&o);
    // The light's point on its triangle, with barycentrics as precise as the walk needs.
    ch->end = manifold_refine_hit(s, (uint)s->lights[o.light].triangle, ch->parent.p + ch->parent.ng,
                                  -ch->parent.ng);
  }
  int m = y->depth - first;
  if (m < 1 || (uint)(y->depth - 1) > delta_depths) return 0;
  if (m > MANIFOLD_MAX_CHAIN) {
    *reason = GPT_COUNTER_FAIL_CHAIN_LONG;
    return 0;
  }
  ch->count = m;
  for (int i = 0; i < m; ++i) ch->v[i] = delta_points[(uint)(first + i - 1) * stride + slot];
  return 1;
}

// The ray from the chain's last vertex toward the target: its first hit is the offset photon.
inline void photon_chain_ray(const SceneData* s, __global GdrRayHit* r, const PhotonChain* ch, float3 target,
                             uint id) {
  GdrManifoldPoint last = ch->v[ch->count - 1];
  Surface sl = surface_at(s, last.prim, last.b1, last.b2);
  float3 d = normalize(target - sl.p);
  write_ray_hit(r, leaving_origin(sl.p, sl.ng, d), d, 0.0f, INFINITY, id);
}

// Whether the path bends through the surface at p (geometric normal ng) from a to b.
inline int chain_transmits(float3 p, float3 ng, float3 a, float3 b) { return dot(ng, a - p) * dot(ng, b - p) < 0.0f; }

// The walk of base photon y (at `origin`) to offset photon `start` along chain ch: the chain from
// the photon's side, each vertex's delta lobe (reflection or transmission) as the base took it.
inline GdrManifoldWalk photon_chain_walk(const SceneData* s, const PhotonChain* ch, GdrManifoldPoint origin,
                                         GdrManifoldPoint start, uint owner) {
  GdrManifoldWalk w;
  const int m = ch->count;
  w.start = start;
  w.end = ch->end;
  w.origin = origin;
  w.count = m;
  w.owner = owner;
  w.pad0 = 0;
  float3 p[MANIFOLD_MAX_CHAIN + 2];  // y, s_m .. s_1, b
  p[0] = manifold_point_on(s, origin);
  for (int i = 0; i < m; ++i) p[i + 1] = manifold_point_on(s, ch->v[m - 1 - i]);
  p[m + 1] = manifold_point_on(s, ch->end);
  for (int i = 0; i < MANIFOLD_MAX_CHAIN; ++i) {
    w.v[i].at = ch->v[i < m ? m - 1 - i : 0];
    w.v[i].flags = MANIFOLD_VERTEX_DELTA;
    w.v[i].h[0] = w.v[i].h[1] = w.v[i].h[2] = w.v[i].pad0 = 0.0f;
    if (i >= m) continue;
    Surface su = surface_at(s, w.v[i].at.prim, w.v[i].at.b1, w.v[i].at.b2);
    if (chain_transmits(p[i + 1], su.ng, p[i], p[i + 2])) w.v[i].flags |= MANIFOLD_VERTEX_TRANSMIT;
  }
  return w;
}

// What a delta vertex at `at` passes on from the light side (toward a) to b under importance
// transport, and the probability of its lobe (*pdf); 0 where it has no such lobe.
inline float3 chain_delta_value(const SceneData* s, GdrManifoldPoint at, int transmit, float3 a, float3 b,
                                float* pdf) {
  Surface su = surface_at(s, at.prim, at.b1, at.b2);
  Bsdf bs = surface_bsdf(s, &su);
  Frame fr = frame_from_normal(su.ns);
  float3 wo = normalize(a - su.p), wi = normalize(b - su.p);
  float3 wo_l = frame_to_local(&fr, wo), wi_l = frame_to_local(&fr, wi);
  BsdfSample so;
  *pdf = 0.0f;
  if (!bsdf_sample_delta_lobe(&bs, wo_l, transmit, &so)) return (float3)(0.0f);
  *pdf = so.pdf;
  return so.weight * so.pdf * shading_normal_correction(wo, wi, su.ng, wo_l.z, wi_l.z);
}

// The chain's points for base and offset, b first: b, s_1 .. s_m and the photon (y, y').
typedef struct PhotonChainPoints {
  float3 base[MANIFOLD_MAX_CHAIN + 2], offset[MANIFOLD_MAX_CHAIN + 2];
} PhotonChainPoints;

// Those of chain ch and its photon sy, and of solved walk R and the offset photon sy2.
inline PhotonChainPoints photon_chain_points(const SceneData* s, const PhotonChain* ch, const GdrManifoldResult* R,
                                             const Surface* sy, const Surface* sy2) {
  PhotonChainPoints pts;
  const int m = ch->count;
  pts.base[0] = pts.offset[0] = manifold_point_on(s, ch->end);
  for (int i = 0; i < m; ++i) {
    pts.base[i + 1] = manifold_point_on(s, ch->v[i]);
    pts.offset[i + 1] = manifold_point_on(s, R->v[m - 1 - i]);
  }
  pts.base[m + 1] = sy->p;
  pts.offset[m + 1] = sy2->p;
  return pts;
}

// The offset photon of solved walk R (points pts) for base photon y (throughput phi) along chain
// ch: its throughput (*phi2), the density ratio p(y') / p(y) of the chain's segments (*ratio), its
// direction toward the chain (*wi2) and b's direction pdfs toward the base and the new chain
// (*pdfs); 0 where it carries nothing (a delta surface at y', a side its shading frame disagrees
// with, a lobe missing).
inline int photon_chain_eval(const SceneData* s, const PhotonChain* ch, const GdrManifoldResult* R,
                             const PhotonChainPoints* pts, const Surface* sy, const Surface* sy2, float3 phi,
                             float3* phi2, float* ratio, float3* wi2, float2* pdfs) {
  const int m = ch->count;
  const float3 *bp = pts->base, *op = pts->offset;
  *pdfs = (float2)(0.0f);
  *wi2 = normalize(op[m] - op[m + 1]);
  Bsdf by2 = surface_bsdf(s, sy2);
  Frame f2 = frame_from_normal(sy2->ns);
  if (bsdf_is_delta(&by2) || !sides_agree(*wi2, sy2->ng, frame_to_local(&f2, *wi2).z)) return 0;
  float pdf, pdf2;
  float3 e = photon_parent_eval(s, &ch->parent, normalize(bp[1] - bp[0]), &pdf);
  float3 e2 = photon_parent_eval(s, &ch->parent, normalize(op[1] - op[0]), &pdf2);
  *pdfs = (float2)(pdf, pdf2);
  float3 value = (float3)(safe_div(e2.x, e.x), safe_div(e2.y, e.y), safe_div(e2.z, e.z));
  float density = safe_div(pdf2, pdf);
  for (int i = 1; i <= m && density > 0.0f; ++i) {
    Surface su = surface_at(s, ch->v[i - 1].prim, ch->v[i - 1].b1, ch->v[i - 1].b2);
    int transmit = chain_transmits(su.p, su.ng, bp[i - 1], bp[i + 1]);
    float lp, lp2;
    float3 v = chain_delta_value(s, ch->v[i - 1], transmit, bp[i - 1], bp[i + 1], &lp);
    float3 v2 = chain_delta_value(s, R->v[m - i], transmit, op[i - 1], op[i + 1], &lp2);
    value *= (float3)(safe_div(v2.x, v.x), safe_div(v2.y, v.y), safe_div(v2.z, v.z));
    density *= safe_div(lp2, lp);
  }
  float g = safe_div(R->g_walk_at_end, R->g_origin_at_end);
  *phi2 = phi * value * g;
  *ratio = density * g;
  return max3(*phi2) > 0.0f && *ratio > 0.0f && isfinite(*ratio) && all(isfinite(*phi2));
}

// What the cosines of a chain's delta vertices do to the light subpath's sums dvc and dvm on the
// way from b to the photon (pts: b, s_1 .. s_m, y; ny the photon's geometric normal): each delta
// vertex divides them by its arrival's cosine and multiplies them by its departure's
// (mis_sums_arrive, mis_sums_scatter), the photon divides them by its own. Not in the heuristic's
// power.
inline float photon_chain_cosines(const SceneData* s, const PhotonChain* ch, const GdrManifoldResult* R,
                                  const float3* pts, float3 ny, int offset) {
  const int m = ch->count;
  float f = 1.0f;
  for (int i = 1; i <= m; ++i) {
    GdrManifoldPoint at = offset ? R->v[m - i] : ch->v[i - 1];
    float3 ng = surface_at(s, at.prim, at.b1, at.b2).ng;
    f *= safe_div(fabs(dot(ng, normalize(pts[i + 1] - pts[i]))), fabs(dot(ng, normalize(pts[i - 1] - pts[i]))));
  }
  return safe_div(f, fabs(dot(ny, normalize(pts[m] - pts[m + 1]))));
}

// The light subpath's MIS sums (bidir/subpath_mis.h) at the offset photon of solved walk R, for
// G-VCM's weights: those base photon y arrived with, its chain moved (points pts, b's direction
// pdfs toward the base and the new chain: photon_chain_eval's). Through a delta vertex dvcm
// becomes 0 and dvc and dvm change by cosines alone (photon_chain_cosines). From a rough parent b
// they are b's sums scattered toward the new chain; from a light point, y's sums with the
// emission's direction pdf and the light's cosine changed (the position pdf is the same point's).
inline void photon_chain_sums(const SceneData* s, const PhotonChain* ch, const GdrManifoldResult* R,
                              const PhotonChainPoints* pts, float2 pdfs, const GdrBidirVertex* y, const Surface* sy,
                              const Surface* sy2, const GdrBidirOptions* o, float* dvcm, float* dvc, float* dvm) {
  const PhotonParent* pa = &ch->parent;
  float3 w = normalize(pts->base[1] - pts->base[0]), w2 = normalize(pts->offset[1] - pts->offset[0]);
  float chain2 = photon_chain_cosines(s, ch, R, pts->offset, sy2->ng, 1);
  *dvcm = *dvc = *dvm = 0.0f;
  if (!(pdfs.y > 0.0f)) return;
  if (pa->kind == GPM_PARENT_SURFACE) {
    float3 wo_l = frame_to_local(&pa->frame, pa->wo), w2_l = frame_to_local(&pa->frame, w2);
    float c = pa->dvcm, v = pa->dvc, m = pa->dvm;
    mis_sums_scatter(0, pdfs.y, bsdf_pdf(&pa->b, w2_l, wo_l), fabs(dot(pa->ng, w2)), o, &c, &v, &m);
    *dvc = v * mis_power_of(chain2, o->mis);
    *dvm = m * mis_power_of(chain2, o->mis);
    return;
  }
  float chain = photon_chain_cosines(s, ch, R, pts->base, sy->ng, 0);
  float scale = safe_div(pdfs.x * fabs(dot(pa->ng, w2)) * chain2, pdfs.y * fabs(dot(pa->ng, w)) * chain);
  if (!(scale > 0.0f) || !isfinite(scale)) return;
  *dvc = y->dvc * mis_power_of(scale, o->mis);
  *dvm = y->dvm * mis_power_of(scale, o->mis);
}
