// G-PM's photon shift (Hua et al. 2017, "Gradient-Domain Photon Density Estimation"; gradientpm/gpm,
// shiftPhoton and shiftPhotonDiffuse). A base path merges light vertex y (a photon) at gather
// point x; its offset merges at the offset gather point x'. The photon keeps its offset from the
// gather point, expressed in the gather points' shading frames (the shift is refused where their
// normals differ); the light subpath before it stays, and its last segment is re-aimed from the
// photon's parent p (the vertex before it: a rough light-subpath vertex, or the light point) at
// that target, the first surface it meets being the offset photon y'. This is a reconnection at
// p: the parent's BSDF (or emission) is evaluated toward y' in place of y, and the photon's
// throughput and its density from p change by
//   throughput: F(w') / F(w) * G(p, y') / G(p, y),   density: pdf(w') G(p, y') / (pdf(w) G(p, y)),
// with F the parent's scattering (or emission) times its cosine, G(p, q) = |cos at q| / |q - p|^2
// (the measure of the photon's surface seen from p) and w, w' the directions from p. A light at
// infinity sends the photon along the same direction from a point of its disc moved with it, the
// ray coming from outside the scene: its G is the cosine at the photon alone (F and pdf are the
// same for both). A parent on a delta surface refuses this shift: the manifold photon shift
// (gbidir/photon_chain.h) takes such photons where it is compiled in.
#pragma once
#include "bidir/subpath_mis.h"
#include "bsdf/transport.h"
#include "core/ray_queue.h"
#include "light/emission.h"
#include "path/scene.h"
#include "path/sides.h"
#include "shared/bidir_types.h"
#include "shared/gbidir_types.h"

// Gather points whose shading normals are further apart than this (cosine) shift no photons:
// their tangent frames would not carry the photon's offset over (the reference's |n - n'|^2 < 0.01).
#define GPM_NORMAL_COS 0.995f

typedef struct PhotonParent {
  int kind;  // GPM_PARENT_*
  float3 p;
  float3 ng;  // surface: its geometric normal; light: the area light's normal there (0 for the others)
  int light;
  Bsdf b;     // surface: its BSDF, shading frame and direction toward the vertex before it
  Frame frame;
  float3 wo;  // infinite: the direction toward the light
  float far;  // infinite: a distance that takes any point of the scene out of it
  float dvcm, dvc, dvm;  // surface: the light subpath's MIS sums as it reached the parent
} PhotonParent;

// A light point the subpath left (not a light at infinity) as a parent.
inline PhotonParent photon_parent_light(const GdrLightOrigin* o) {
  PhotonParent pa;
  pa.kind = GPM_PARENT_LIGHT;
  pa.p = vload3(0, o->p);
  pa.ng = vload3(0, o->n);
  pa.light = o->light;
  return pa;
}

// Stored light vertex q as a parent.
inline PhotonParent photon_parent_vertex(const SceneData* s, const GdrBidirVertex* q) {
  PhotonParent pa;
  Surface sq = surface_at(s, q->prim, q->u, q->v);
  pa.kind = GPM_PARENT_SURFACE;
  pa.light = -1;
  pa.p = sq.p;
  pa.ng = sq.ng;
  pa.b = surface_bsdf(s, &sq);
  pa.frame = frame_from_normal(sq.ns);
  pa.wo = vload3(0, q->wo);
  pa.dvcm = q->dvcm;
  pa.dvc = q->dvc;
  pa.dvm = q->dvm;
  return pa;
}

// The parent of store entry `entry` (vertex j of light subpath `slot`: entry = j * stride + slot),
// photon y.
inline PhotonParent photon_parent(const SceneData* s, __global const GdrBidirVertex* store,
                                  __global const GdrLightOrigin* origins, uint stride, uint entry,
                                  const GdrBidirVertex* y) {
  PhotonParent pa;
  pa.kind = GPM_PARENT_NONE;
  pa.light = -1;
  uint j = entry / stride, slot = entry % stride;
  if (y->depth == 1) {
    GdrLightOrigin o = origins[slot];
    if (o.light < 0) return pa;
    if (light_is_infinite(s, o.light)) {
      pa.kind = GPM_PARENT_INFINITE;
      pa.light = o.light;
      pa.wo = vload3(0, y->wo);
      pa.far = 2.5f * s->lights[o.light].scene_radius;
      pa.ng = (float3)(0.0f);
      return pa;
    }
    return photon_parent_light(&o);
  }
  if (j == 0) return pa;
  GdrBidirVertex q = store[(j - 1) * stride + slot];
  if (q.depth != y->depth - 1) return pa;  // a delta vertex lies between (gbidir/photon_chain.h)
  return photon_parent_vertex(s, &q);
}

// What the parent sends along w (unit, leaving it), up to a factor the same for every w: the
// BSDF in importance transport with its cosine and shading-normal correction, or the light's
// emission with its cosine; *pdf: the density with which the light subpath drew w there.
inline float3 photon_parent_eval(const SceneData* s, const PhotonParent* pa, float3 w, float* pdf) {
  *pdf = 0.0f;
  if (pa->kind == GPM_PARENT_LIGHT) {
    __global const GdrLight* l = &s->lights[pa->light];
    *pdf = light_emission_pdf_dir(s, pa->light, pa->ng, w);
    if (l->type == LIGHT_AREA) return area_radiance(s, pa->light, pa->ng, w) * fabs(dot(pa->ng, w));
    if (l->type == LIGHT_SPOT) return (float3)(spot_falloff(l, w));
    return (float3)(1.0f);
  }
  if (pa->kind != GPM_PARENT_SURFACE) return (float3)(0.0f);
  float3 wo_l = frame_to_local(&pa->frame, pa->wo), wi_l = frame_to_local(&pa->frame, w);
  if (!sides_agree(w, pa->ng, wi_l.z)) return (float3)(0.0f);
  *pdf = bsdf_pdf(&pa->b, wo_l, wi_l);
  return bsdf_eval_transport(&pa->b, wo_l, wi_l, TRANSPORT_IMPORTANCE) *
         shading_normal_correction(pa->wo, w, pa->ng, wo_l.z, wi_l.z);
}

// |cos at q (normal nq)| / |q - p|^2.
inline float photon_geometry(float3 p, float3 q, float3 nq) {
  float3 d = q - p;
  float d2 = dot(d, d);
  return d2 > 0.0f ? fabs(dot(nq, d)) / (d2 * sqrt(d2)) : 0.0f;
}

// Where photon py (merged at gather point px, shading normal nx) goes for gather point px2
// (normal nx2); 0 where the normals differ too much.
inline int photon_shift_target(float3 px, float3 nx, float3 px2, float3 nx2, float3 py, float3* target) {
  if (!(dot(nx, nx2) > GPM_NORMAL_COS)) return 0;
  Frame f = frame_from_normal(nx), f2 = frame_from_normal(nx2);
  *target = px2 + frame_to_world(&f2, frame_to_local(&f, py - px));
  return 1;
}

// The direction from a photon at q toward its parent.
inline float3 photon_toward_parent(const PhotonParent* pa, float3 q) {
  return pa->kind == GPM_PARENT_INFINITE ? pa->wo : normalize(pa->p - q);
}

// The ray from the parent toward the target: its first hit is the offset photon.
inline void photon_shift_ray(__global GdrRayHit* r, const PhotonParent* pa, float3 target, uint id) {
  if (pa->kind == GPM_PARENT_INFINITE) {
    write_ray_hit(r, target + pa->far * pa->wo, -pa->wo, 0.0f, INFINITY, id);
    return;
  }
  float3 d = normalize(target - pa->p);
  float3 o = dot(pa->ng, pa->ng) > 0.0f ? leaving_origin(pa->p, pa->ng, d) : pa->p;
  write_ray_hit(r, o, d, 0.0f, INFINITY, id);
}

// A refused shift's ray: Embree skips it (tnear > tfar) and reports no hit.
inline void photon_no_ray(__global GdrRayHit* r, uint id) {
  write_ray_hit(r, (float3)(0.0f), (float3)(0.0f, 0.0f, 1.0f), 1.0f, 0.0f, id);
}

// The offset photon at surface sy2 (found from parent pa) for base photon y (throughput phi, at
// py with geometric normal ny): its throughput (*phi2), the density ratio of its last segment
// (*ratio, p(y') / p(y)) and the parent's direction pdfs toward y and y' (*pdfs; 1 for a light at
// infinity). 0 where y' could not be a photon (a delta surface, or the side its shading frame
// disagrees with) or the parent sends nothing toward it.
inline int photon_shift_eval(const SceneData* s, const PhotonParent* pa, float3 py, float3 ny, float3 phi,
                             const Surface* sy2, float3* phi2, float* ratio, float2* pdfs) {
  Bsdf by2 = surface_bsdf(s, sy2);
  float3 w2 = -photon_toward_parent(pa, sy2->p);
  Frame f2 = frame_from_normal(sy2->ns);
  if (bsdf_is_delta(&by2) || !sides_agree(-w2, sy2->ng, frame_to_local(&f2, -w2).z)) return 0;
  if (pa->kind == GPM_PARENT_INFINITE) {
    // Parallel light: the photon's area density from the light's disc, and what arrives per area,
    // go with the cosine at the surface (G(p, q) without its distance).
    float c = fabs(dot(ny, pa->wo)), c2 = fabs(dot(sy2->ng, pa->wo));
    *ratio = c > 0.0f ? c2 / c : 0.0f;
    *phi2 = phi * *ratio;
    *pdfs = (float2)(1.0f);
    return *ratio > 0.0f && isfinite(*ratio);
  }
  float3 w = normalize(py - pa->p);
  float pdf, pdf2;
  float3 e = photon_parent_eval(s, pa, w, &pdf), e2 = photon_parent_eval(s, pa, w2, &pdf2);
  *pdfs = (float2)(pdf, pdf2);
  float g = photon_geometry(pa->p, py, ny), g2 = photon_geometry(pa->p, sy2->p, sy2->ng);
  float3 scale = (float3)(e.x > 0.0f ? e2.x / e.x : 0.0f, e.y > 0.0f ? e2.y / e.y : 0.0f,
                          e.z > 0.0f ? e2.z / e.z : 0.0f);
  *phi2 = phi * scale * (g > 0.0f ? g2 / g : 0.0f);
  *ratio = pdf * g > 0.0f ? (pdf2 * g2) / (pdf * g) : 0.0f;
  return max3(*phi2) > 0.0f && *ratio > 0.0f && isfinite(*ratio) && all(isfinite(*phi2));
}

// The light subpath's MIS sums (bidir/subpath_mis.h) at the offset photon sy2, for G-VCM's weights:
// those base photon y (at py, geometric normal ny) arrived with, its last segment re-aimed; pdfs:
// the parent's direction pdfs toward y and sy2 (photon_shift_eval's). From a rough parent they
// are the parent's sums scattered toward sy2 and arrived there; from a light point, y's sums with
// the emission's direction pdf, the light's cosine and the segment changed (the position pdf is
// the same point's); from a light at infinity (same direction, no length), with the arrival's
// cosine changed.
inline void photon_shift_sums(const PhotonParent* pa, const GdrBidirVertex* y, float3 py, float3 ny,
                              const Surface* sy2, float2 pdfs, const GdrBidirOptions* o, float* dvcm, float* dvc,
                              float* dvm) {
  float3 w2 = -photon_toward_parent(pa, sy2->p);
  float cos2 = fabs(dot(sy2->ng, w2));
  *dvcm = *dvc = *dvm = 0.0f;
  if (pa->kind == GPM_PARENT_SURFACE) {
    if (!(pdfs.y > 0.0f)) return;
    float3 wo_l = frame_to_local(&pa->frame, pa->wo), w2_l = frame_to_local(&pa->frame, w2);
    float c = pa->dvcm, v = pa->dvc, m = pa->dvm;
    mis_sums_scatter(0, pdfs.y, bsdf_pdf(&pa->b, w2_l, wo_l), fabs(dot(pa->ng, w2)), o, &c, &v, &m);
    mis_sums_arrive(length(sy2->p - pa->p), cos2, 1, o->mis, &c, &v, &m);
    *dvcm = c;
    *dvc = v;
    *dvm = m;
    return;
  }
  float3 w = -photon_toward_parent(pa, py);
  float cos1 = fabs(dot(ny, w));
  if (!(cos2 > 0.0f)) return;
  float arrive = cos1 / cos2, emit = 1.0f, length2 = 1.0f;
  if (pa->kind == GPM_PARENT_LIGHT) {
    if (!(pdfs.y > 0.0f)) return;
    emit = pdfs.x / pdfs.y;
    float3 d = py - pa->p, d2 = sy2->p - pa->p;
    length2 = dot(d2, d2) / dot(d, d);
    // The light's cosine: an area light's at its point (1 for the others, whose dvm is 0 anyway).
    float cl = fabs(dot(pa->ng, w)), cl2 = fabs(dot(pa->ng, w2));
    if (cl > 0.0f && cl2 > 0.0f) {
      float scale = mis_power_of(emit * arrive * cl2 / cl, o->mis);
      *dvc = y->dvc * scale;
      *dvm = y->dvm * scale;
    }
  } else {
    *dvc = y->dvc * mis_power_of(arrive, o->mis);
    *dvm = y->dvm * mis_power_of(arrive, o->mis);
  }
  *dvcm = y->dvcm * mis_power_of(emit * arrive * length2, o->mis);
}
