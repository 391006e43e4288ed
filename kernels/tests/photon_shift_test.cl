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
