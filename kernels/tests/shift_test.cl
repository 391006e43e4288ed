// Test kernels for the gradient-domain shift mappings (kernels/shift) and their MIS weights
// (kernels/path/mis.h): the host drives them with random configurations and checks
// invertibility, Jacobians and weights.
#include "path/mis.h"
#include "shift/half_vector.h"
#include "shift/reconnect.h"

// in[i]: wo, wi, wo_off (float4 each, w unused), and params (transmitted, eta_material).
// out[i]: wi_off (xyz) + jacobian (w); then the reverse shift of wi_off from wo_off back at wo:
// wi_back (xyz) + jacobian_back (w). ok[i]: forward and reverse both defined.
__kernel void shift_half_vector_roundtrip(uint count, __global const float4* in, __global float4* out,
                                          __global int* ok) {
  uint i = get_global_id(0);
  if (i >= count) return;
  float3 wo = normalize(in[4 * i + 0].xyz), wi = normalize(in[4 * i + 1].xyz), wo_off = normalize(in[4 * i + 2].xyz);
  int transmitted = (int)in[4 * i + 3].x;
  float eta_material = in[4 * i + 3].y;
  // Relative IOR across the base's interface for its own side of wo.
  float eta_rel = transmitted ? (wo.z > 0.0f ? eta_material : 1.0f / eta_material) : 1.0f;
  float3 wi_off, wi_back;
  float j = 0.0f, jb = 0.0f;
  int a = shift_half_vector(wo, wi, transmitted, eta_rel, wo_off, eta_material, &wi_off, &j);
  float eta_rel_off = transmitted ? (wo_off.z > 0.0f ? eta_material : 1.0f / eta_material) : 1.0f;
  int b = a && shift_half_vector(wo_off, wi_off, transmitted, eta_rel_off, wo, eta_material, &wi_back, &jb);
  out[2 * i + 0] = (float4)(a ? wi_off : (float3)(0.0f), j);
  out[2 * i + 1] = (float4)(b ? wi_back : (float3)(0.0f), jb);
  ok[i] = a && b;
}

// Maps each direction wi[i] (of the base at wo) to the offset at wo_off, for finite differences.
__kernel void shift_half_vector_map(uint count, float4 wo4, float4 wo_off4, int transmitted, float eta_material,
                                    __global const float4* wi, __global float4* wi_off) {
  uint i = get_global_id(0);
  if (i >= count) return;
  float3 wo = normalize(wo4.xyz), wo_off = normalize(wo_off4.xyz);
  float eta_rel = transmitted ? (wo.z > 0.0f ? eta_material : 1.0f / eta_material) : 1.0f;
  float3 w;
  float j;
  int ok = shift_half_vector(wo, normalize(wi[i].xyz), transmitted, eta_rel, wo_off, eta_material, &w, &j);
  wi_off[i] = ok ? (float4)(w, j) : (float4)(0.0f);
}

// reconnect_jacobian for (x, y, z, nz) quadruples.
__kernel void shift_reconnect_jacobian(uint count, __global const float4* in, __global float* out) {
  uint i = get_global_id(0);
  if (i >= count) return;
  out[i] = reconnect_jacobian(in[4 * i].xyz, in[4 * i + 1].xyz, in[4 * i + 2].xyz, normalize(in[4 * i + 3].xyz));
}

// The gpt_weight of every way a path x is found, summed: by BSDF sampling (pdf p.x) and by light
// sampling (p.y) as a base, and as the offset of the partner each technique's shift pairs it
// with (ratios p(y)|J| / p(x): ratio.x under BSDF sampling, ratio.y under light sampling).
__kernel void shift_weights_sum(uint count, __global const float2* pdfs, __global const float2* ratio,
                                __global float* out) {
  uint i = get_global_id(0);
  if (i >= count) return;
  float2 p = pdfs[i], r = ratio[i];
  out[i] = gpt_weight(p.x, p.y, r.x) + gpt_weight(p.y, p.x, r.y) + gpt_weight(p.x, p.y, 1.0f / r.x) +
           gpt_weight(p.y, p.x, 1.0f / r.y);
}
