// Test kernels for G-PM's photon shift (kernels/gbidir/photon_shift.h): the host checks that the
// photon's target inverts and keeps its distance from the gather point, the geometry term against
// the solid angle a small patch subtends, and G-VCM's light-side sums of photons left in place,
// also (built with the manifold solver's defines and GDR_GVCM) behind delta vertices
// (gbidir/photon_chain.h).
#include "gbidir/photon_shift.h"
#if defined(GDR_MANIFOLD)
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
  int reason;
  kind[e] = GPM_PARENT_NONE;
  if (photon_parent(&s, store, origins, stride, e, &y).kind != GPM_PARENT_NONE ||
      !photon_chain(&s, store, origins, delta_points, delta_depths, stride, e, &y, &ch, &reason)) {
    return;
  }
  GdrManifoldResult R;
  R.g_walk = R.g_origin = 1.0f;
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
#endif
