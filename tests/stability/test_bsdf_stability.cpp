// Numerical hygiene of the BSDFs at the edges of their domain: grazing directions (cos 1e-7),
// directions exactly in the tangent plane, roughness at and below the minimum (1e-4, 1e-6),
// index-matched dielectrics (eta exactly 1, and 1 + 1e-6), total internal reflection, slightly
// non-normalized inputs and extreme uniforms. Every output must be finite, pdfs >= 0, and a
// returned sample must carry a positive pdf and a finite, non-negative weight.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bsdf/bsdf_harness.h"

namespace gdr::test {
namespace {

std::vector<GdrMaterial> edge_materials() {
  std::vector<GdrMaterial> m;
  m.push_back(diffuse_material(1.0f));
  GdrMaterial two = diffuse_material(1.0f);
  two.twosided = 1;
  m.push_back(two);
  m.push_back(conductor_material(BSDF_CONDUCTOR));
  m.push_back(mirror_material());
  for (int d : {MICROFACET_BECKMANN, MICROFACET_GGX}) {
    for (float a : {1e-4f, 1e-6f, 0.0f, 1.0f, 3.0f}) {
      m.push_back(conductor_material(BSDF_ROUGH_CONDUCTOR, d, a, a));
      m.push_back(conductor_material(BSDF_ROUGH_CONDUCTOR, d, a, 0.5f));
      for (float eta : {1.5f, 1.0f / 1.5f, 1.0f, 1.000001f, 1.001f}) {
        m.push_back(dielectric_material(BSDF_ROUGH_DIELECTRIC, eta, d, a));
      }
      m.push_back(plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 1.0f, 1, d, a));
      m.push_back(plastic_material(BSDF_ROUGH_PLASTIC, 1.0f, 1.0f, 0, d, a));
    }
    GdrMaterial mirror = mirror_material(BSDF_ROUGH_CONDUCTOR);
    mirror.distribution = d;
    mirror.alpha_u = mirror.alpha_v = 1e-4f;
    m.push_back(mirror);
  }
  for (float eta : {1.5f, 1.0f / 1.5f, 1.0f, 1.000001f, 0.0f}) {
    m.push_back(dielectric_material(BSDF_DIELECTRIC, eta));
    m.push_back(dielectric_material(BSDF_THIN_DIELECTRIC, eta));
    m.push_back(plastic_material(BSDF_PLASTIC, eta, 1.0f, 1));
  }
  return m;
}

std::vector<cl_float4> edge_directions() {
  std::vector<cl_float4> d;
  for (double c : {1.0, 0.9, 0.3, 1e-3, 1e-7, 0.0, -0.0, -1e-7, -1e-3, -0.5, -1.0}) {
    for (double phi : {0.0, 0.7, M_PI / 2, 2.5}) d.push_back(dir_cos(c, phi));
  }
  // Slightly off unit length (1 +- 1e-3), and a pure tangent direction.
  size_t n = d.size();
  for (size_t i = 0; i < n; i += 3) {
    cl_float4 v = d[i];
    float s = (i % 2) ? 1.001f : 0.999f;
    d.push_back(f4(v.s[0] * s, v.s[1] * s, v.s[2] * s));
  }
  d.push_back(f4(1, 0, 0));
  return d;
}

bool finite4(const cl_float4& v) {
  return std::isfinite(v.s[0]) && std::isfinite(v.s[1]) && std::isfinite(v.s[2]) &&
         std::isfinite(v.s[3]);
}

TEST(BsdfStability, EdgeCasesStayFinite) {
  BsdfKernels& k = bsdf_kernels();
  std::vector<cl_float4> dirs = edge_directions();
  const float one_minus = 1.0f - 0x1.0p-24f;  // the largest uniform the RNG produces
  std::vector<cl_float4> us = {f4(0, 0, 0), f4(one_minus, one_minus, one_minus),
                               f4(0.5f, 0, one_minus), f4(one_minus, 0.5f, 0),
                               f4(0.03f, 0.999f, 0.001f), f4(0.97f, 0.25f, 0.75f)};
  std::vector<cl_float4> wo, u, wo_pairs, wi_pairs;
  for (const cl_float4& d : dirs) {
    for (const cl_float4& uu : us) {
      wo.push_back(d);
      u.push_back(uu);
    }
    for (const cl_float4& e : dirs) {
      wo_pairs.push_back(d);
      wi_pairs.push_back(e);
    }
  }
  int index = 0;
  for (const GdrMaterial& m : edge_materials()) {
    SCOPED_TRACE("material " + std::to_string(index++) + " type " + std::to_string(m.type) +
                 " alpha " + std::to_string(m.alpha_u) + " eta " + std::to_string(m.eta[0]));
    SampleBatch s = k.sample(m, wo, u);
    for (size_t i = 0; i < wo.size(); ++i) {
      ASSERT_TRUE(finite4(s.wi_pdf[i]) && finite4(s.weight_eta[i])) << "sample " << i;
      if (!s.flags[i].s[0]) continue;
      ASSERT_GT(s.wi_pdf[i].s[3], 0.0f) << i;
      for (int c = 0; c < 3; ++c) ASSERT_GE(s.weight_eta[i].s[c], 0.0f) << i;
      ASSERT_GT(s.weight_eta[i].s[3], 0.0f) << i;
      double len = std::sqrt(s.wi_pdf[i].s[0] * s.wi_pdf[i].s[0] +
                             s.wi_pdf[i].s[1] * s.wi_pdf[i].s[1] +
                             s.wi_pdf[i].s[2] * s.wi_pdf[i].s[2]);
      ASSERT_NEAR(len, 1.0, 1e-4) << "sampled directions are unit vectors, sample " << i;
    }
    std::vector<cl_float4> ev = k.eval(m, wo_pairs, wi_pairs);
    for (size_t i = 0; i < ev.size(); ++i) {
      ASSERT_TRUE(finite4(ev[i])) << "pair " << i;
      ASSERT_GE(ev[i].s[3], 0.0f) << "pair " << i;
      for (int c = 0; c < 3; ++c) ASSERT_GE(ev[i].s[c], 0.0f) << "pair " << i;
    }
  }
}

}  // namespace
}  // namespace gdr::test
