// Test kernel for the manifold photon shift (kernels/gbidir/photon_chain.h), built with the manifold
// solver's defines and GDR_GVCM: the host checks that G-VCM's light-side sums of a photon whose
// chain did not move are the photon's own.
#include "gbidir/photon_chain.h"

// For each store entry e of a traced batch (vertex j of subpath slot at j * stride + slot, below
// `stored` of its subpath) whose parent is a delta vertex: photon_chain_sums with the walk's result
// the base chain itself and the offset photon the base's, out[2 e] = (the photon's dvcm, the
// recomputed dvcm, its dvm, the recomputed dvm), out[2 e + 1] = (its dvc, the recomputed dvc, the
// chain's length, 0), and kind[e] the kind of the chain's rough end (GPM_PARENT_SURFACE or
// GPM_PARENT_LIGHT; -1 for no stored vertex, GPM_PARENT_NONE for no chain).
__kernel void photon_chain_sums_unmoved(GdrPtParams params, GdrBidirOptions opts, uint entries, uint stride,
                                        __global const GdrBidirPathState* light_paths,
                                        __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                        __global const GdrManifoldPoint* delta_points, uint delta_depths,
                                        __global float4* out, __global int* kind, SCENE_DATA_ARGS) {
  uint e = get_global_id(0);
  if (e >= entries) return;
  uint j = e / stride, slot = e % stride;
  kind[e] = -1;
  if (slot >= params.pixel_count || (int)j >= light_paths[slot].stored) return;
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
  for (int i = 0; i < ch.count; ++i) R.v[ch.count - 1 - i] = ch.v[i];
  Surface sy = surface_at(&s, y.prim, y.u, y.v);
  float dvcm, dvc, dvm;
  photon_chain_sums(&s, &ch, &R, &y, &sy, &sy, &opts, &dvcm, &dvc, &dvm);
  kind[e] = ch.parent.kind;
  out[2 * e] = (float4)(y.dvcm, dvcm, y.dvm, dvm);
  out[2 * e + 1] = (float4)(y.dvc, dvc, (float)ch.count, 0.0f);
}
