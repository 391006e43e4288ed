// Test kernels for G-PM's photon shift (kernels/gbidir/photon_shift.h): the host checks that the
// photon's target inverts and keeps its distance from the gather point, the geometry term against
// the solid angle a small patch subtends, and G-VCM's light-side sums of photons left in place,
// also (built with the manifold solver's defines and GDR_GVCM) behind delta vertices
// (gbidir/photon_chain.h), where the manifold photon shift's walks are also checked against finite
// differences and shifted there and back, also by light tracing's shift.
#include "gbidir/photon_shift.h"
#if defined(GDR_MANIFOLD)
#include "gbidir/light_tracing.h"
#include "gbidir/photon_chain.h"
#endif

// Whether store entry e of a traced batch (vertex j of subpath slot at j * stride + slot) holds a
// vertex: below `stored` of its subpath, within the batch's paths; else kind[e] is -1.
inline int batch_entry_stored(const GdrPtParams* params, uint e, uint stride,
                              __global const GdrBidirPathState* light_paths, __global int* kind) {
  uint j = e / stride, slot = e % stride;
  kind[e] = -1;
  return slot < params->pixel_count && (int)j < light_paths[slot].stored;
}

// in[5 i ..]: gather point x, its normal, gather point x', its normal, photon y. out[2 i]: the
// target for x' (w: 1 where the shift is defined), out[2 i + 1]: that target taken back to x.
__kernel void photon_shift_target_roundtrip(uint count, __global const float4* in, __global float4* out) {
  uint i = get_global_id(0);
  if (i >= count) return;
  float3 px = in[5 * i].xyz, nx = normalize(in[5 * i + 1].xyz), px2 = in[5 * i + 2].xyz;
  float3 nx2 = normalize(in[5 * i + 3].xyz), py = in[5 * i + 4].xyz;
  float3 t = (float3)(0.0f), back = (float3)(0.0f);
  int a = photon_shift_target(px, nx, px2, nx2, py, &t);
  int b = a && photon_shift_target(px2, nx2, px, nx, t, &back);
  out[2 * i] = (float4)(t, a ? 1.0f : 0.0f);
  out[2 * i + 1] = (float4)(back, b ? 1.0f : 0.0f);
}

// photon_geometry for (p, q, nq) triples.
__kernel void photon_geometry_eval(uint count, __global const float4* in, __global float* out) {
  uint i = get_global_id(0);
  if (i >= count) return;
  out[i] = photon_geometry(in[3 * i].xyz, in[3 * i + 1].xyz, normalize(in[3 * i + 2].xyz));
}

// G-VCM's light-side sums of a photon shifted onto itself (photon_shift_sums with the offset photon
// at the base photon's own point): for each store entry e of a traced batch (vertex j of subpath
// slot at j * stride + slot, below `stored` of its subpath), out[2 e] = (the photon's dvcm, the
// recomputed dvcm, its dvm, the recomputed dvm), out[2 e + 1] = (its dvc, the recomputed dvc, 0,
// 0) (photon_shift_eval gives the parent's pdfs), and
// kind[e] its parent's kind (GPM_PARENT_*; -1 for no stored vertex, GPM_PARENT_NONE also where
// the shift is refused).
__kernel void photon_shift_sums_unshifted(GdrPtParams params, GdrBidirOptions opts, uint entries, uint stride,
                                          __global const GdrCamera* camera,
                                          __global const GdrBidirPathState* light_paths,
                                          __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                          __global float4* out, __global int* kind, SCENE_DATA_ARGS) {
  uint e = get_global_id(0);
  if (e >= entries || !batch_entry_stored(&params, e, stride, light_paths, kind)) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrBidirVertex y = store[e];
  PhotonParent pa = photon_parent(&s, store, origins, stride, e, &y);
  Surface sy = surface_at(&s, y.prim, y.u, y.v);
  float dvcm = 0.0f, dvc = 0.0f, dvm = 0.0f, ratio;
  float3 phi2;
  float2 pdfs;
  int shifted = pa.kind != GPM_PARENT_NONE &&
                photon_shift_eval(&s, &pa, sy.p, sy.ng, vload3(0, y.throughput), &sy, &phi2, &ratio, &pdfs);
  kind[e] = shifted ? pa.kind : GPM_PARENT_NONE;
  if (shifted) photon_shift_sums(&pa, &y, sy.p, sy.ng, &sy, pdfs, &opts, &dvcm, &dvc, &dvm);
  out[2 * e] = (float4)(y.dvcm, dvcm, y.dvm, dvm);
  out[2 * e + 1] = (float4)(y.dvc, dvc, 0.0f, 0.0f);
}

#if defined(GDR_MANIFOLD)
// Whether photon y (store entry e) has a delta parent and the chain behind it (*ch).
inline int photon_behind_chain(const SceneData* s, __global const GdrBidirVertex* store,
                               __global const GdrLightOrigin* origins, __global const GdrManifoldPoint* delta_points,
                               uint delta_depths, uint stride, uint e, const GdrBidirVertex* y, PhotonChain* ch) {
  int reason;
  return photon_parent(s, store, origins, stride, e, y).kind == GPM_PARENT_NONE &&
         photon_chain(s, store, origins, delta_points, delta_depths, stride, e, y, ch, &reason);
}

// G-VCM's sums of a photon whose parent is a delta vertex, its chain left where it is
// (photon_chain_sums with the walk's result the base chain itself and the offset photon the
// base's): for each store entry e as above, out[2 e] = (the photon's dvcm, the recomputed dvcm, its
// dvm, the recomputed dvm), out[2 e + 1] = (its dvc, the recomputed dvc, the chain's length, 0),
// and kind[e] the kind of the chain's rough end (GPM_PARENT_SURFACE or GPM_PARENT_LIGHT;
// GPM_PARENT_NONE for no chain).
__kernel void photon_chain_sums_unmoved(GdrPtParams params, GdrBidirOptions opts, uint entries, uint stride,
                                        __global const GdrBidirPathState* light_paths,
                                        __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                        __global const GdrManifoldPoint* delta_points, uint delta_depths,
                                        __global float4* out, __global int* kind, SCENE_DATA_ARGS) {
  uint e = get_global_id(0);
  if (e >= entries || !batch_entry_stored(&params, e, stride, light_paths, kind)) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrBidirVertex y = store[e];
  PhotonChain ch;
  kind[e] = GPM_PARENT_NONE;
  if (!photon_behind_chain(&s, store, origins, delta_points, delta_depths, stride, e, &y, &ch)) return;
  GdrManifoldResult R;
  R.g_walk = R.g_origin = R.g_walk_at_end = R.g_origin_at_end = 1.0f;
  for (int i = 0; i < ch.count; ++i) R.v[ch.count - 1 - i] = ch.v[i];
  Surface sy = surface_at(&s, y.prim, y.u, y.v);
  PhotonChainPoints pts = photon_chain_points(&s, &ch, &R, &sy, &sy);
  float3 phi2, wi2;
  float ratio, dvcm = 0.0f, dvc = 0.0f, dvm = 0.0f;
  float2 pdfs;
  if (!photon_chain_eval(&s, &ch, &R, &pts, &sy, &sy, vload3(0, y.throughput), &phi2, &ratio, &wi2, &pdfs)) return;
  photon_chain_sums(&s, &ch, &R, &pts, pdfs, &y, &sy, &sy, &opts, &dvcm, &dvc, &dvm);
  kind[e] = ch.parent.kind;
  out[2 * e] = (float4)(y.dvcm, dvcm, y.dvm, dvm);
  out[2 * e + 1] = (float4)(y.dvc, dvc, (float)ch.count, 0.0f);
}

// The manifold photon shift's walks and their evaluation, for a density and round-trip check: for
// each store entry e whose photon y has a chain of delta vertices behind it (photon_chain), six
// walks along the chain with b fixed, at walks[6 k ..] (k from counters[0], owner e), from y's
// base chain to: y itself, y moved by +-h along its surface's tangents s and t, and y moved by d
// along s (the offset photon y'). kind[e]: the chain end's kind (GPM_PARENT_*), or GPM_PARENT_NONE.
__kernel void photon_chain_test_walks(GdrPtParams params, uint entries, uint stride,
                                      __global const GdrBidirPathState* light_paths,
                                      __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                      __global const GdrManifoldPoint* delta_points, uint delta_depths, float h,
                                      float d, __global GdrManifoldWalk* walks, __global uint* counters,
                                      __global int* kind, SCENE_DATA_ARGS) {
  uint e = get_global_id(0);
  if (e >= entries || !batch_entry_stored(&params, e, stride, light_paths, kind)) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrBidirVertex y = store[e];
  PhotonChain ch;
  kind[e] = GPM_PARENT_NONE;
  if (!photon_behind_chain(&s, store, origins, delta_points, delta_depths, stride, e, &y, &ch)) return;
  kind[e] = ch.parent.kind;
  Surface sy = surface_at(&s, y.prim, y.u, y.v);
  Frame f = frame_from_normal(sy.ng);
  const float3 moves[6] = {(float3)(0.0f), h * f.s, -h * f.s, h * f.t, -h * f.t, d * f.s};
  GdrManifoldPoint origin = {y.prim, y.u, y.v};
  uint k = atomic_inc(&counters[0]);
  for (int i = 0; i < 6; ++i) {
    // The moved point on y's triangle's plane (the photon's surface, flat in the scenes tested).
    GdrManifoldPoint at = i == 0 ? origin : manifold_refine_hit(&s, y.prim, sy.p + moves[i] + sy.ng, -sy.ng);
    walks[6 * k + i] = photon_chain_walk(&s, &ch, origin, at, e);
  }
}

// The chain of entry e's photon solved by walk R: the offset photon's chain, for a shift back.
inline PhotonChain photon_chain_moved(const PhotonChain* ch, const GdrManifoldResult* R) {
  PhotonChain c = *ch;
  for (int i = 0; i < ch->count; ++i) c.v[i] = R->v[ch->count - 1 - i];
  return c;
}

// Rebuilds the chain of the entry that owns walk slot k (photon_chain_test_walks).
inline void photon_chain_test_entry(const SceneData* s, __global const GdrManifoldWalk* walks, uint k,
                                    __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                    __global const GdrManifoldPoint* delta_points, uint delta_depths, uint stride,
                                    GdrBidirVertex* y, PhotonChain* ch) {
  uint e = walks[6 * k].owner;
  int reason;
  *y = store[e];
  photon_chain(s, store, origins, delta_points, delta_depths, stride, e, y, ch, &reason);
}

// For each walk slot k whose shift to y' (walk 6 k + 5) was solved: the walk back from y' along
// its solved chain to y, at back[k] (a copy of walk 6 k + 5 where that walk failed).
__kernel void photon_chain_test_back(GdrPtParams params, uint count, __global const GdrManifoldWalk* walks,
                                     __global const GdrManifoldResult* results, __global const GdrBidirVertex* store,
                                     __global const GdrLightOrigin* origins,
                                     __global const GdrManifoldPoint* delta_points, uint delta_depths, uint stride,
                                     __global GdrManifoldWalk* back, SCENE_DATA_ARGS) {
  uint k = get_global_id(0);
  if (k >= count) return;
  back[k] = walks[6 * k + 5];
  GdrManifoldResult R = results[6 * k + 5];
  if (R.status != 0) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrBidirVertex y;
  PhotonChain ch;
  photon_chain_test_entry(&s, walks, k, store, origins, delta_points, delta_depths, stride, &y, &ch);
  PhotonChain ch2 = photon_chain_moved(&ch, &R);
  back[k] = photon_chain_walk(&s, &ch2, walks[6 * k + 5].start, walks[6 * k].start, k);
}

// For each walk slot k, out[9 k ..]: for walks 0 .. 4, (b's direction toward the solved chain,
// 1 where solved); out[9 k + 5] = (|d w_b / dA(y)| of walk 0 (its g_walk_at_end), the chain's
// length, 0, 0); out[9 k + 6] = (p(y') / p(y) of the shift to y', p(y) / p(y') of
// the shift back, 1 where each was evaluated); out[9 k + 7] = (the throughput the shift back gives
// y, over y's own, per channel; 0); out[9 k + 8] = light tracing's walked shift of y (seen by the
// camera) to y' and back (lt_offset_walked): (R(y -> y') R(y' -> y), the way back's value over
// y's own light-tracing value times R(y' -> y), 1 where both were formed, 0).
__kernel void photon_chain_test_eval(GdrPtParams params, GdrBidirOptions opts, __global const GdrCamera* camera,
                                     uint count, __global const GdrManifoldWalk* walks,
                                     __global const GdrManifoldResult* results,
                                     __global const GdrManifoldResult* back_results,
                                     __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                     __global const GdrManifoldPoint* delta_points, uint delta_depths, uint stride,
                                     __global float4* out, SCENE_DATA_ARGS) {
  uint k = get_global_id(0);
  if (k >= count) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrBidirVertex y;
  PhotonChain ch;
  photon_chain_test_entry(&s, walks, k, store, origins, delta_points, delta_depths, stride, &y, &ch);
  const int m = ch.count;
  float3 b = manifold_point_on(&s, ch.end);
  for (int i = 0; i < 5; ++i) {
    GdrManifoldResult R = results[6 * k + i];
    float3 w = R.status == 0 ? normalize(manifold_point_on(&s, R.v[m - 1]) - b) : (float3)(0.0f);
    out[9 * k + i] = (float4)(w, R.status == 0 ? 1.0f : 0.0f);
  }
  Surface sy = surface_at(&s, y.prim, y.u, y.v);
  GdrManifoldResult R0 = results[6 * k];
  out[9 * k + 5] = (float4)(R0.status == 0 ? R0.g_walk_at_end : 0.0f, (float)m, 0.0f, 0.0f);
  out[9 * k + 6] = out[9 * k + 7] = out[9 * k + 8] = (float4)(0.0f);
  GdrManifoldResult RA = results[6 * k + 5], RB = back_results[k];
  if (RA.status != 0) return;
  GdrManifoldPoint at = walks[6 * k + 5].start;
  Surface sy2 = surface_at(&s, at.prim, at.b1, at.b2);
  PhotonChainPoints pa = photon_chain_points(&s, &ch, &RA, &sy, &sy2);
  float3 phi = vload3(0, y.throughput), phi2, wi2, phi_back;
  float ratio_a = 0.0f, ratio_b = 0.0f;
  float2 pdfs;
  int a = photon_chain_eval(&s, &ch, &RA, &pa, &sy, &sy2, phi, &phi2, &ratio_a, &wi2, &pdfs);
  int back = 0;
  if (a && RB.status == 0) {
    PhotonChain ch2 = photon_chain_moved(&ch, &RA);
    PhotonChainPoints pb = photon_chain_points(&s, &ch2, &RB, &sy2, &sy);
    back = photon_chain_eval(&s, &ch2, &RB, &pb, &sy2, &sy, phi2, &phi_back, &ratio_b, &wi2, &pdfs);
  }
  out[9 * k + 6] = (float4)(ratio_a, ratio_b, a ? 1.0f : 0.0f, back ? 1.0f : 0.0f);
  if (back) {
    out[9 * k + 7] = (float4)(safe_div(phi_back.x, phi.x), safe_div(phi_back.y, phi.y), safe_div(phi_back.z, phi.z), 0.0f);
  }
  // Light tracing's shift of y there and back, where the camera sees both points.
  GdrCamera cam = *camera;
  CameraProjection pr;
  if (RB.status != 0 || !camera_project(&cam, sy.p, &pr)) return;
  GdrBidirVertex yv, yback;
  float3 v, v2;
  float r, r2;
  if (!lt_offset_walked(&s, &cam, &opts, &ch, &RA, &y, &sy, &sy2, &yv, &v, &r)) return;
  yv.prim = at.prim;
  yv.u = at.b1;
  yv.v = at.b2;
  PhotonChain ch2 = photon_chain_moved(&ch, &RA);
  if (!lt_offset_walked(&s, &cam, &opts, &ch2, &RB, &yv, &sy2, &sy, &yback, &v2, &r2)) return;
  // y's own light-tracing value, as bidir_light_shade splats it.
  Bsdf by = surface_bsdf(&s, &sy);
  Frame f = frame_from_normal(sy.ns);
  float scale;
  float3 fy = camera_connection(&cam, &pr, &by, &f, sy.ng, vload3(0, y.wo), y.dvcm, y.dvc, &opts, 1, &scale);
  float expect = dot(phi * fy * scale, (float3)(1.0f)) * r2;
  if (!(expect > 0.0f)) return;
  out[9 * k + 8] = (float4)(r * r2, dot(v2, (float3)(1.0f)) / expect, 1.0f, 0.0f);
}
#endif
