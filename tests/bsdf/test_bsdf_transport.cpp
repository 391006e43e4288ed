// Transport modes of the BSDF call (kernels/bsdf/transport.h): radiance transport is bsdf.h's
// call unchanged; importance transport evaluates the adjoint BSDF, f*(a, b) = f(b, a), for every
// type (the refraction scaling is the one asymmetric part), its samples carry the matching
// weights, and the shading-normal correction has Veach's form. Every value comes from the kernels.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bsdf/bsdf_harness.h"

namespace gdr {
namespace {

using test::bsdf_kernels;
using test::f4;

constexpr int kRadiance = 0, kImportance = 1;  // TRANSPORT_*

struct Evals {
  std::vector<cl_float4> f_pdf, rev;
};

Evals eval_transport(const GdrMaterial& m, int mode, const std::vector<cl_float4>& wo,
                     const std::vector<cl_float4>& wi) {
  auto& k = bsdf_kernels();
  test::DeviceMaterial mat = k.upload(m);
  cl_uint n = cl_uint(wo.size());
  Buffer<cl_float4> a(k.context(), wo), b(k.context(), wi), out(k.context(), n), rev(k.context(), n);
  k.program()
      ->kernel("bsdf_eval_transport_batch")
      .args(mat.material, mat.coating_tables, test::reflectance_of(m), mode, a, b, n, out, rev)
      .run(n);
  return {out.read(), rev.read()};
}

test::SampleBatch sample_transport(const GdrMaterial& m, int mode, const std::vector<cl_float4>& wo,
                                   const std::vector<cl_float4>& u) {
  auto& k = bsdf_kernels();
  test::DeviceMaterial mat = k.upload(m);
  cl_uint n = cl_uint(wo.size());
  Buffer<cl_float4> a(k.context(), wo), ub(k.context(), u), wi_pdf(k.context(), n), weight(k.context(), n);
  Buffer<cl_int4> flags(k.context(), n);
  k.program()
      ->kernel("bsdf_sample_transport_batch")
      .args(mat.material, mat.coating_tables, test::reflectance_of(m), mode, a, ub, n, wi_pdf, weight, flags)
      .run(n);
  return {wi_pdf.read(), weight.read(), flags.read()};
}

std::vector<GdrMaterial> materials() {
  return {test::diffuse_material(0.7f),
          test::conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_GGX, 0.3f, 0.3f),
          test::dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_GGX, 0.3f),
          test::dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.33f, MICROFACET_BECKMANN, 0.2f),
          test::plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 0.5f, 0, MICROFACET_GGX, 0.3f)};
}

// Random direction pairs (seed 17): both above, or one above and one below for transmitting
// types (either way round).
void direction_pairs(bool transmits, int n, std::vector<cl_float4>* a, std::vector<cl_float4>* b) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    double ca = 0.05 + 0.95 * u(rng), cb = 0.05 + 0.95 * u(rng);
    if (transmits && i % 2 == 1) cb = -cb;
    if (transmits && i % 4 == 3) {
      ca = -ca;
      cb = -cb;
    }
    a->push_back(test::dir_cos(ca, 2 * M_PI * u(rng)));
    b->push_back(test::dir_cos(cb, 2 * M_PI * u(rng)));
  }
}

TEST(BsdfTransport, RadianceModeIsTheRadianceCall) {
  for (const GdrMaterial& m : materials()) {
    std::vector<cl_float4> a, b;
    direction_pairs(m.type == BSDF_ROUGH_DIELECTRIC, 256, &a, &b);
    Evals got = eval_transport(m, kRadiance, a, b);
    std::vector<cl_float4> ref = bsdf_kernels().eval(m, a, b);
    for (size_t i = 0; i < a.size(); ++i)
      for (int c = 0; c < 4; ++c) ASSERT_EQ(got.f_pdf[i].s[c], ref[i].s[c]) << "type " << m.type << " pair " << i;
  }
}

// f*(a, b) |cos b| / |cos b| = f(b, a): importance transport evaluated from a toward b equals the
// radiance BSDF with the two directions swapped, across a refraction too. The reverse pdf is the
// forward pdf of the swapped pair.
TEST(BsdfTransport, ImportanceModeEvaluatesTheAdjoint) {
  for (const GdrMaterial& m : materials()) {
    std::vector<cl_float4> a, b;
    direction_pairs(m.type == BSDF_ROUGH_DIELECTRIC, 512, &a, &b);
    Evals imp = eval_transport(m, kImportance, a, b);
    Evals swapped = eval_transport(m, kRadiance, b, a);
    int nonzero = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        double adj = imp.f_pdf[i].s[c] / std::fabs(b[i].s[2]);
        double ref = swapped.f_pdf[i].s[c] / std::fabs(a[i].s[2]);
        ASSERT_NEAR(adj, ref, 2e-4 * std::max(1.0, ref)) << "type " << m.type << " pair " << i << " channel " << c;
        nonzero += ref > 0;
      }
      ASSERT_FLOAT_EQ(imp.rev[i].s[3], swapped.f_pdf[i].s[3]) << "reverse pdf, type " << m.type << " pair " << i;
    }
    EXPECT_GT(nonzero, 300) << "type " << m.type << ": too few pairs with a nonzero value to show anything";
  }
}

// A sample's direction and pdf do not depend on the mode; its weight gains eta_rel^2 on a
// refraction (smooth and rough dielectrics, both sides) and nothing on a reflection, and for a
// rough type it is the importance-mode eval over the pdf.
TEST(BsdfTransport, ImportanceSamplesCarryTheAdjointWeight) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const GdrMaterial& m : {test::dielectric_material(BSDF_DIELECTRIC, 1.5f),
                               test::dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_GGX, 0.3f)}) {
    std::vector<cl_float4> wo, us;
    for (int i = 0; i < 2048; ++i) {
      double c = (0.05 + 0.95 * u(rng)) * (i % 2 ? -1 : 1);
      wo.push_back(test::dir_cos(c, 2 * M_PI * u(rng)));
      us.push_back(f4(float(u(rng)), float(u(rng)), float(u(rng))));
    }
    test::SampleBatch rad = sample_transport(m, kRadiance, wo, us), imp = sample_transport(m, kImportance, wo, us);
    int refracted = 0;
    std::vector<cl_float4> ok_wo, ok_wi;
    std::vector<size_t> ok_i;
    for (size_t i = 0; i < wo.size(); ++i) {
      ASSERT_EQ(rad.flags[i].s[0], imp.flags[i].s[0]);
      if (!rad.flags[i].s[0]) continue;
      for (int c = 0; c < 4; ++c) ASSERT_EQ(rad.wi_pdf[i].s[c], imp.wi_pdf[i].s[c]) << "sample " << i;
      double eta = rad.weight_eta[i].s[3], scale = rad.flags[i].s[2] ? eta * eta : 1.0;
      refracted += rad.flags[i].s[2];
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(imp.weight_eta[i].s[c], rad.weight_eta[i].s[c] * scale, 1e-5 * imp.weight_eta[i].s[c] + 1e-7);
      if (!rad.flags[i].s[1]) {
        ok_wo.push_back(wo[i]);
        ok_wi.push_back(rad.wi_pdf[i]);
        ok_i.push_back(i);
      }
    }
    EXPECT_GT(refracted, 500) << "type " << m.type;
    if (ok_i.empty()) continue;
    Evals e = eval_transport(m, kImportance, ok_wo, ok_wi);
    for (size_t j = 0; j < ok_i.size(); ++j) {
      size_t i = ok_i[j];
      for (int c = 0; c < 3; ++c) {
        double w = e.f_pdf[j].s[c] / e.f_pdf[j].s[3];
        ASSERT_NEAR(imp.weight_eta[i].s[c], w, 2e-3 * w + 1e-6) << "rough sample " << i;
      }
    }
  }
}

// |cos_s(wo)| |cos_g(wi)| / (|cos_g(wo)| |cos_s(wi)|): 1 where the normals agree, Veach's ratio
// where they do not, 0 where wo grazes the geometry.
TEST(BsdfTransport, ShadingNormalCorrectionHasVeachsForm) {
  auto& k = bsdf_kernels();
  const double t = 0.3;  // the shading normal is tilted by t radians about y
  cl_float4 ng = f4(0, 0, 1), ns = f4(float(std::sin(t)), 0, float(std::cos(t)));
  std::vector<cl_float4> wo = {test::dir_cos(0.8, 0.4), test::dir_cos(0.6, 1.0), f4(1, 0, 0)};
  std::vector<cl_float4> wi = {test::dir_cos(0.3, 2.0), test::dir_cos(0.9, 4.0), test::dir_cos(0.5, 0.0)};
  std::vector<cl_float4> ngs(3, ng), nss = {ng, ns, ns};
  Buffer<cl_float4> a(k.context(), wo), b(k.context(), wi), g(k.context(), ngs), s(k.context(), nss);
  Buffer<float> out(k.context(), 3);
  k.program()->kernel("shading_normal_correction_batch").args(a, b, g, s, cl_uint(3), out).run(3);
  std::vector<float> c = out.read();
  auto d = [](const cl_float4& x, const cl_float4& y) { return double(x.s[0]) * y.s[0] + double(x.s[1]) * y.s[1] + double(x.s[2]) * y.s[2]; };
  EXPECT_NEAR(c[0], 1.0, 1e-6);
  double expected = std::fabs(d(wo[1], ns)) * std::fabs(d(wi[1], ng)) / (std::fabs(d(wo[1], ng)) * std::fabs(d(wi[1], ns)));
  EXPECT_NEAR(c[1], expected, 1e-5 * expected);
  EXPECT_NE(c[1], 1.0f);
  EXPECT_EQ(c[2], 0.0f);
}

}  // namespace
}  // namespace gdr
