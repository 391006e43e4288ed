// Test kernel for G-BDPT's light-tracing shift (kernels/gbidir/light_tracing.h): a light vertex
// shifted to another point and back.
#include "gbidir/light_tracing.h"

// For each store entry e of a traced batch (vertex j of subpath slot at j * stride + slot, below
// `stored` of its subpath) that the camera sees (occlusion aside), x: the vertex is shifted to
// the point of entry j of one of the next subpaths that the camera sees (y1: any rough point,
// sharing x's parent), and y back to x1. out[e] = (R(x -> y) R(y -> x), the reverse's value over x's own
// light-tracing value times R(y -> x), 0, 0): both 1 for a shift whose densities and Jacobians
// invert and whose re-aimed sums give x's own weight back. kind[e]: x's parent (GPM_PARENT_*),
// -1 where the pair was not formed.
__kernel void lt_offset_round_trip(GdrPtParams params, GdrBidirOptions opts, uint entries, uint stride,
                                   __global const GdrCamera* camera, __global const GdrBidirPathState* light_paths,
                                   __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                   __global float4* out, __global int* kind, SCENE_DATA_ARGS) {
  uint e = get_global_id(0);
  if (e >= entries) return;
  uint j = e / stride, slot = e % stride;
  kind[e] = -1;
  out[e] = (float4)(0.0f);
  if (slot >= params.pixel_count || (int)j >= light_paths[slot].stored) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrCamera cam = *camera;
  GdrBidirVertex x = store[e], src;
  PhotonParent pa = photon_parent(&s, store, origins, stride, e, &x);
  CameraProjection pr;
  Surface sx = surface_at(&s, x.prim, x.u, x.v), sy;
  if (pa.kind == GPM_PARENT_NONE || !camera_project(&cam, sx.p, &pr)) return;
  int found = 0;
  for (uint t = 1; t <= 64 && !found; ++t) {
    uint other = (slot + t) % params.pixel_count;
    if ((int)j >= light_paths[other].stored) continue;
    src = store[j * stride + other];
    sy = surface_at(&s, src.prim, src.u, src.v);
    CameraProjection po;
    found = camera_project(&cam, sy.p, &po);
  }
  if (!found) return;
  GdrBidirVertex y, back;
  float3 v, v2;
  float r, r2;
  if (!lt_offset(&s, &cam, &opts, &pa, &x, &sx, &sy, &y, &v, &r)) return;
  y.prim = src.prim;
  y.u = src.u;
  y.v = src.v;
  if (!lt_offset(&s, &cam, &opts, &pa, &y, &sy, &sx, &back, &v2, &r2)) return;
  // x's own light-tracing value, as bidir_light_shade splats it.
  Bsdf b = surface_bsdf(&s, &sx);
  Frame f = frame_from_normal(sx.ns);
  float scale;
  float3 fx = camera_connection(&cam, &pr, &b, &f, sx.ng, vload3(0, x.wo), x.dvcm, x.dvc, &opts, 1, &scale);
  float3 c = vload3(0, x.throughput) * fx * scale;
  float expect = (c.x + c.y + c.z) * r2;
  if (!(expect > 0.0f)) return;
  kind[e] = pa.kind;
  out[e] = (float4)(r * r2, (v2.x + v2.y + v2.z) / expect, 0.0f, 0.0f);
}

