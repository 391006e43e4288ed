// Batched access to the BSDF interface for the host tests and benchmarks: the host only draws
// inputs and does statistics; every value comes from kernels/bsdf.
#include "bsdf/transport.h"
#include "core/rng.h"

// One sample per item: wo[i] (xyz), uniforms u[i] (xyz). Outputs: wi_pdf = (wi, pdf),
// weight_eta = (weight, eta), flags = (ok, delta, transmitted, 0); zeros when there is no sample.
__kernel void bsdf_sample_batch(__global const GdrMaterial* mat, __global const float* coating,
                                float4 reflectance,
                                __global const float4* wo, __global const float4* u, uint n,
                                __global float4* wi_pdf, __global float4* weight_eta,
                                __global int4* flags) {
  uint i = get_global_id(0);
  if (i >= n) return;
  Bsdf b = bsdf_from_material(mat, coating, reflectance.xyz);
  BsdfSample s;
  int ok = bsdf_sample(&b, wo[i].xyz, u[i].xyz, &s);
  if (!ok) {
    wi_pdf[i] = (float4)(0.0f);
    weight_eta[i] = (float4)(0.0f);
    flags[i] = (int4)(0);
    return;
  }
  wi_pdf[i] = (float4)(s.wi, s.pdf);
  weight_eta[i] = (float4)(s.weight, s.eta);
  flags[i] = (int4)(1, s.delta, s.transmitted, 0);
}

// n samples for one wo, uniforms from the engine's RNG keyed by (seed, pixel 0, sample i).
__kernel void bsdf_sample_rng(__global const GdrMaterial* mat, __global const float* coating,
                              float4 reflectance, float4 wo,
                              uint seed, uint n, __global float4* wi_pdf,
                              __global float4* weight_eta, __global int4* flags) {
  uint i = get_global_id(0);
  if (i >= n) return;
  Bsdf b = bsdf_from_material(mat, coating, reflectance.xyz);
  float4 u = rng_block(seed, 0u, i, 0u);
  BsdfSample s;
  int ok = bsdf_sample(&b, wo.xyz, u.xyz, &s);
  if (!ok) {
    wi_pdf[i] = (float4)(0.0f);
    weight_eta[i] = (float4)(0.0f);
    flags[i] = (int4)(0);
    return;
  }
  wi_pdf[i] = (float4)(s.wi, s.pdf);
  weight_eta[i] = (float4)(s.weight, s.eta);
  flags[i] = (int4)(1, s.delta, s.transmitted, 0);
}

// Throughput-only sampling for the benchmark: sums the weight so nothing is optimized away.
__kernel void bsdf_sample_bench(__global const GdrMaterial* mat, __global const float* coating,
                                float4 reflectance, float4 wo,
                                uint seed, uint n, __global float* out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  Bsdf b = bsdf_from_material(mat, coating, reflectance.xyz);
  float4 u = rng_block(seed, 0u, i, 0u);
  BsdfSample s;
  int ok = bsdf_sample(&b, wo.xyz, u.xyz, &s);
  out[i] = ok ? s.weight.x + s.pdf : 0.0f;
}

// eval_pdf[i] = (bsdf_eval(wo[i], wi[i]), bsdf_pdf(wo[i], wi[i])).
__kernel void bsdf_eval_batch(__global const GdrMaterial* mat, __global const float* coating,
                              float4 reflectance,
                              __global const float4* wo, __global const float4* wi, uint n,
                              __global float4* eval_pdf) {
  uint i = get_global_id(0);
  if (i >= n) return;
  Bsdf b = bsdf_from_material(mat, coating, reflectance.xyz);
  eval_pdf[i] = (float4)(bsdf_eval(&b, wo[i].xyz, wi[i].xyz), bsdf_pdf(&b, wo[i].xyz, wi[i].xyz));
}

// bsdf_pdf(wo, wi) on the tensor grid theta[0..nt) x phi[0..np) (row-major, phi fastest): the
// host integrates it over the chi-square bins.
__kernel void bsdf_pdf_grid(__global const GdrMaterial* mat, __global const float* coating,
                            float4 reflectance, float4 wo,
                            __global const float* theta, uint nt, __global const float* phi,
                            uint np, __global float* pdf) {
  uint i = get_global_id(0);
  if (i >= nt * np) return;
  float t = theta[i / np], p = phi[i % np];
  float st = sin(t);
  float3 wi = (float3)(st * cos(p), st * sin(p), cos(t));
  Bsdf b = bsdf_from_material(mat, coating, reflectance.xyz);
  pdf[i] = bsdf_pdf(&b, wo.xyz, wi);
}

// Per material: (roughness, is_delta, has_diffuse_lobe, has_delta_lobe).
__kernel void bsdf_info(__global const GdrMaterial* mat, __global const float* coating,
                        float4 reflectance, __global float4* out) {
  if (get_global_id(0) != 0) return;
  Bsdf b = bsdf_from_material(mat, coating, reflectance.xyz);
  out[0] = (float4)(bsdf_roughness(&b), (float)bsdf_is_delta(&b), (float)bsdf_has_diffuse_lobe(&b),
                    (float)bsdf_has_delta_lobe(&b));
}

// Half-vector helpers: out = (h, ok) and the Jacobian, for reflection (eta_rel == 1 and wo, wi on
// the same side) or refraction.
__kernel void bsdf_half_vector_batch(__global const float4* wo, __global const float4* wi,
                                     float eta_rel, uint n, __global float4* h_ok,
                                     __global float* jacobian) {
  uint i = get_global_id(0);
  if (i >= n) return;
  float3 o = wo[i].xyz, w = wi[i].xyz, h = (float3)(0.0f);
  int reflect = o.z * w.z > 0.0f;
  int ok = reflect ? half_vector_reflect(o, w, &h) : half_vector_refract(o, w, eta_rel, &h);
  h_ok[i] = (float4)(h, (float)ok);
  jacobian[i] = !ok ? 0.0f : reflect ? half_jacobian_reflect(w, h)
                                     : half_jacobian_refract(o, w, h, eta_rel);
}

// Transport modes (bsdf/transport.h). out[i] = (bsdf_eval_transport(wo[i], wi[i], mode), pdf)
// and rev[i] = (0, 0, 0, reverse pdf).
__kernel void bsdf_eval_transport_batch(__global const GdrMaterial* mat, __global const float* coating,
                                        float4 reflectance, int mode, __global const float4* wo,
                                        __global const float4* wi, uint n, __global float4* out,
                                        __global float4* rev) {
  uint i = get_global_id(0);
  if (i >= n) return;
  Bsdf b = bsdf_from_material(mat, coating, reflectance.xyz);
  float pdf, pdf_rev;
  float3 f = bsdf_eval_pdf(&b, wo[i].xyz, wi[i].xyz, mode, &pdf, &pdf_rev);
  out[i] = (float4)(f, pdf);
  rev[i] = (float4)(0.0f, 0.0f, 0.0f, pdf_rev);
}

// bsdf_sample_transport with uniforms u[i]: weight_eta = (weight, eta), flags = (ok, delta,
// transmitted, 0).
__kernel void bsdf_sample_transport_batch(__global const GdrMaterial* mat, __global const float* coating,
                                          float4 reflectance, int mode, __global const float4* wo,
                                          __global const float4* u, uint n, __global float4* wi_pdf,
                                          __global float4* weight_eta, __global int4* flags) {
  uint i = get_global_id(0);
  if (i >= n) return;
  Bsdf b = bsdf_from_material(mat, coating, reflectance.xyz);
  BsdfSample s;
  int ok = bsdf_sample_transport(&b, wo[i].xyz, u[i].xyz, mode, &s);
  wi_pdf[i] = ok ? (float4)(s.wi, s.pdf) : (float4)(0.0f);
  weight_eta[i] = ok ? (float4)(s.weight, s.eta) : (float4)(0.0f);
  flags[i] = ok ? (int4)(1, s.delta, s.transmitted, 0) : (int4)(0);
}

// c[i] = shading_normal_correction for world wo[i], wi[i], geometric normal ng[i] and the
// shading normal ns[i].
__kernel void shading_normal_correction_batch(__global const float4* wo, __global const float4* wi,
                                              __global const float4* ng, __global const float4* ns, uint n,
                                              __global float* c) {
  uint i = get_global_id(0);
  if (i >= n) return;
  c[i] = shading_normal_correction(wo[i].xyz, wi[i].xyz, ng[i].xyz, dot(wo[i].xyz, ns[i].xyz),
                                   dot(wi[i].xyz, ns[i].xyz));
}
