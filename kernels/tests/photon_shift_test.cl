// Test kernels for G-PM's photon shift (kernels/gbidir/photon_shift.h): the host checks that the
// photon's target inverts and keeps its distance from the gather point, and the geometry term
// against the solid angle a small patch subtends.
#include "gbidir/photon_shift.h"

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
  if (e >= entries) return;
  uint j = e / stride, slot = e % stride;
  kind[e] = -1;
  if (slot >= params.pixel_count || (int)j >= light_paths[slot].stored) return;
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
