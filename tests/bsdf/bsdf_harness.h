// Host side of the BSDF tests: builds materials and drives the kernels in
// kernels/tests/bsdf_test.cl. No BSDF physics here; only inputs, transfers and bookkeeping.
#pragma once
#include <CL/cl.h>

#include <cmath>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "device/context.h"
#include "render/coating_tables.h"
#include "shared/coating_table.h"
#include "shared/scene_types.h"
#include "support/devices.h"

namespace gdr::test {

inline cl_float4 f4(float x, float y, float z, float w = 0.0f) {
  cl_float4 v;
  v.s[0] = x;
  v.s[1] = y;
  v.s[2] = z;
  v.s[3] = w;
  return v;
}

// Unit direction with the given cos(theta) and azimuth phi.
inline cl_float4 dir_cos(double cos_theta, double phi) {
  double s = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return f4(float(s * std::cos(phi)), float(s * std::sin(phi)), float(cos_theta));
}

inline void set3(float* a, float x, float y, float z) {
  a[0] = x;
  a[1] = y;
  a[2] = z;
  a[3] = 0.0f;
}

// A material of `type` with white reflectances, eta 1.5, alpha 0.1, GGX, one-sided.
inline GdrMaterial base_material(int type) {
  GdrMaterial m{};
  m.type = type;
  m.twosided = 0;
  m.distribution = MICROFACET_GGX;
  m.reflectance_texture = -1;
  set3(m.reflectance, 1, 1, 1);
  set3(m.specular_reflectance, 1, 1, 1);
  set3(m.specular_transmittance, 1, 1, 1);
  set3(m.eta, 1.5f, 1.5f, 1.5f);
  set3(m.k, 0, 0, 0);
  m.alpha_u = m.alpha_v = 0.1f;
  m.nonlinear = 0;
  m.coating_table = -1;
  return m;
}

inline GdrMaterial diffuse_material(float r = 1.0f) {
  GdrMaterial m = base_material(BSDF_DIFFUSE);
  set3(m.reflectance, r, r, r);
  return m;
}

// Gold-like complex IOR (eta, k per RGB channel).
inline GdrMaterial conductor_material(int type, int distribution = MICROFACET_GGX,
                                      float au = 0.1f, float av = 0.1f) {
  GdrMaterial m = base_material(type);
  set3(m.eta, 0.143f, 0.374f, 1.442f);
  set3(m.k, 3.983f, 2.385f, 1.603f);
  m.distribution = distribution;
  m.alpha_u = au;
  m.alpha_v = av;
  return m;
}

// The perfect mirror ("none"): eta = 0 on every channel.
inline GdrMaterial mirror_material(int type = BSDF_CONDUCTOR) {
  GdrMaterial m = base_material(type);
  set3(m.eta, 0, 0, 0);
  set3(m.k, 0, 0, 0);
  return m;
}

inline GdrMaterial dielectric_material(int type, float eta, int distribution = MICROFACET_GGX,
                                       float alpha = 0.1f) {
  GdrMaterial m = base_material(type);
  set3(m.eta, eta, eta, eta);
  m.distribution = distribution;
  m.alpha_u = m.alpha_v = alpha;
  return m;
}

inline GdrMaterial plastic_material(int type, float eta, float r, int nonlinear = 0,
                                    int distribution = MICROFACET_GGX, float alpha = 0.1f) {
  GdrMaterial m = dielectric_material(type, eta, distribution, alpha);
  set3(m.reflectance, r, r, r);
  m.nonlinear = nonlinear;
  return m;
}

inline cl_float4 reflectance_of(const GdrMaterial& m) {
  return f4(m.reflectance[0], m.reflectance[1], m.reflectance[2]);
}

struct SampleBatch {
  std::vector<cl_float4> wi_pdf;      // (wi, pdf)
  std::vector<cl_float4> weight_eta;  // (weight, eta)
  std::vector<cl_int4> flags;         // (ok, delta, transmitted, 0)
};

// A material on the device with its coating table, as a scene upload makes them.
struct DeviceMaterial {
  Buffer<GdrMaterial> material;
  Buffer<float> coating_tables;
};

// The BSDF test kernels on the default device (built once per process).
class BsdfKernels {
 public:
  BsdfKernels() : ctx_(default_context()), program_(ctx_.program("tests/bsdf_test.cl")) {}

  Context& context() { return ctx_; }

  // The material's coating table (render/coating_tables.h: built by the engine's kernels, once
  // per coating_key, as a scene shares them) and its coating_table offset in it.
  const std::vector<float>& coating_table(const GdrMaterial& m, int* offset) {
    std::vector<GdrMaterial> one{m};
    auto it = tables_.find(coating_key(m));
    if (it == tables_.end()) {
      std::vector<float> tables;
      build_coating_tables(ctx_, one, tables);
      it = tables_.emplace(coating_key(m), tables).first;
    }
    *offset = coating_table_size(m.type) > 0 ? 0 : -1;
    return it->second;
  }

  DeviceMaterial upload(const GdrMaterial& m) {
    GdrMaterial coated = m;
    const std::vector<float>& table = coating_table(m, &coated.coating_table);
    return {Buffer<GdrMaterial>(ctx_, std::vector<GdrMaterial>{coated}), Buffer<float>(ctx_, table)};
  }

  SampleBatch sample_rng(const GdrMaterial& m, cl_float4 wo, unsigned seed, unsigned n) {
    DeviceMaterial mat = upload(m);
    Buffer<cl_float4> wi_pdf(ctx_, n), weight_eta(ctx_, n);
    Buffer<cl_int4> flags(ctx_, n);
    program_->kernel("bsdf_sample_rng")
        .args(mat.material, mat.coating_tables, reflectance_of(m), wo, seed, n, wi_pdf,
              weight_eta, flags)
        .run(n);
    return {wi_pdf.read(), weight_eta.read(), flags.read()};
  }

  SampleBatch sample(const GdrMaterial& m, const std::vector<cl_float4>& wo,
                     const std::vector<cl_float4>& u) {
    unsigned n = static_cast<unsigned>(wo.size());
    DeviceMaterial mat = upload(m);
    Buffer<cl_float4> wo_buf(ctx_, wo), u_buf(ctx_, u), wi_pdf(ctx_, n), weight_eta(ctx_, n);
    Buffer<cl_int4> flags(ctx_, n);
    program_->kernel("bsdf_sample_batch")
        .args(mat.material, mat.coating_tables, reflectance_of(m), wo_buf, u_buf, n, wi_pdf,
              weight_eta, flags)
        .run(n);
    return {wi_pdf.read(), weight_eta.read(), flags.read()};
  }

  // (eval.xyz, pdf) per pair.
  std::vector<cl_float4> eval(const GdrMaterial& m, const std::vector<cl_float4>& wo,
                              const std::vector<cl_float4>& wi) {
    unsigned n = static_cast<unsigned>(wo.size());
    DeviceMaterial mat = upload(m);
    Buffer<cl_float4> wo_buf(ctx_, wo), wi_buf(ctx_, wi), out(ctx_, n);
    program_->kernel("bsdf_eval_batch")
        .args(mat.material, mat.coating_tables, reflectance_of(m), wo_buf, wi_buf, n, out)
        .run(n);
    return out.read();
  }

  std::vector<float> pdf_grid(const GdrMaterial& m, cl_float4 wo, const std::vector<float>& theta,
                              const std::vector<float>& phi) {
    unsigned nt = static_cast<unsigned>(theta.size()), np = static_cast<unsigned>(phi.size());
    DeviceMaterial mat = upload(m);
    Buffer<float> t(ctx_, theta), p(ctx_, phi), out(ctx_, size_t(nt) * np);
    program_->kernel("bsdf_pdf_grid")
        .args(mat.material, mat.coating_tables, reflectance_of(m), wo, t, nt, p, np, out)
        .run(size_t(nt) * np);
    return out.read();
  }

  // (roughness, is_delta, has_diffuse_lobe, has_delta_lobe).
  cl_float4 info(const GdrMaterial& m) {
    DeviceMaterial mat = upload(m);
    Buffer<cl_float4> out(ctx_, 1);
    program_->kernel("bsdf_info")
        .args(mat.material, mat.coating_tables, reflectance_of(m), out)
        .run(1);
    return out.read()[0];
  }

  std::shared_ptr<Program> program() { return program_; }

 private:
  Context& ctx_;
  std::shared_ptr<Program> program_;
  std::map<std::array<uint32_t, 5>, std::vector<float>> tables_;
};

inline BsdfKernels& bsdf_kernels() {
  static BsdfKernels kernels;
  return kernels;
}

}  // namespace gdr::test
