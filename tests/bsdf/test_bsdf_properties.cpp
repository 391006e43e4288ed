// Properties every BSDF must have, checked on the kernels: sampling weights agree with eval/pdf,
// reciprocity (and its generalized form for refraction), energy conservation (white furnace),
// exact delta directions and Fresnel values, and the roughness classification.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "bsdf/bsdf_harness.h"

namespace gdr::test {
namespace {

struct Named {
  std::string name;
  GdrMaterial m;
};

std::vector<Named> non_delta_materials() {
  GdrMaterial aniso = conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_GGX, 0.05f, 0.4f);
  GdrMaterial two = diffuse_material(0.8f);
  two.twosided = 1;
  return {
      {"diffuse", diffuse_material(0.8f)},
      {"diffuse_twosided", two},
      {"rough_conductor_ggx", conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_GGX, 0.3f, 0.3f)},
      {"rough_conductor_beckmann",
       conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_BECKMANN, 0.2f, 0.2f)},
      {"rough_conductor_aniso", aniso},
      {"rough_dielectric_ggx", dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_GGX, 0.3f)},
      {"rough_dielectric_beckmann",
       dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.33f, MICROFACET_BECKMANN, 0.2f)},
      {"plastic", plastic_material(BSDF_PLASTIC, 1.5f, 0.6f)},
      {"plastic_nonlinear", plastic_material(BSDF_PLASTIC, 1.5f, 0.6f, 1)},
      {"rough_plastic_ggx", plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 0.6f, 0, MICROFACET_GGX, 0.2f)},
      {"rough_plastic_beckmann",
       plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 0.6f, 1, MICROFACET_BECKMANN, 0.3f)},
  };
}

bool two_sided_transport(const GdrMaterial& m) {
  return m.type == BSDF_ROUGH_DIELECTRIC || m.type == BSDF_DIELECTRIC ||
         m.type == BSDF_THIN_DIELECTRIC || m.twosided;
}

// Random unit directions, uniform on the sphere (or the upper hemisphere).
std::vector<cl_float4> random_dirs(size_t n, unsigned seed, bool upper) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<cl_float4> d(n);
  for (auto& v : d) {
    double z = upper ? u(rng) : 2.0 * u(rng) - 1.0;
    v = dir_cos(z, 2 * M_PI * u(rng));
  }
  return d;
}

double rel_diff(double a, double b, double floor = 1e-6) {
  return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), floor});
}

// For every sampled non-delta direction, weight == eval / pdf and the reported pdf == bsdf_pdf.
// Deterministic inputs (seed 7); tolerance 1e-3 relative (float rounding of the same formulas
// computed in two ways), for 99.9% of the samples and 1e-2 for all.
TEST(BsdfProperties, SampleWeightMatchesEvalOverPdf) {
  BsdfKernels& k = bsdf_kernels();
  const size_t n = 20000;
  for (const Named& c : non_delta_materials()) {
    SCOPED_TRACE(c.name);
    std::vector<cl_float4> wo = random_dirs(n, 7, !two_sided_transport(c.m));
    std::vector<cl_float4> u = random_dirs(n, 8, false);
    for (auto& v : u) v = f4(0.5f * (v.s[0] + 1), 0.5f * (v.s[1] + 1), 0.5f * (v.s[2] + 1));
    SampleBatch s = k.sample(c.m, wo, u);
    std::vector<cl_float4> wi(n);
    for (size_t i = 0; i < n; ++i) wi[i] = s.wi_pdf[i];
    std::vector<cl_float4> ev = k.eval(c.m, wo, wi);
    size_t checked = 0, loose = 0;
    for (size_t i = 0; i < n; ++i) {
      if (!s.flags[i].s[0] || s.flags[i].s[1]) continue;
      ++checked;
      double pdf = s.wi_pdf[i].s[3], pdf_eval = ev[i].s[3];
      double worst = rel_diff(pdf, pdf_eval);
      for (int ch = 0; ch < 3; ++ch) {
        worst = std::max(worst, rel_diff(s.weight_eta[i].s[ch], ev[i].s[ch] / pdf_eval));
      }
      ASSERT_LT(worst, 1e-2) << "sample " << i << ": pdf " << pdf << " vs " << pdf_eval
                             << ", weight " << s.weight_eta[i].s[0] << " vs eval/pdf "
                             << ev[i].s[0] / pdf_eval;
      if (worst > 1e-3) ++loose;
    }
    EXPECT_GT(checked, n / 4);
    EXPECT_LE(loose, checked / 1000) << loose << " of " << checked;
  }
}

// f(wo, wi) = f(wi, wo) for reflection. For refraction with radiance scaling the generalized
// form holds: f(wo, wi) eta_wi^2 = f(wi, wo) eta_wo^2 (eta_x: IOR on x's side), i.e.
// f / eta_o^2 is symmetric for the importance-transport BTDF. Tolerance: 2e-3 relative for 99.5%
// of the pairs (the half vector is computed from the two directions in either order).
TEST(BsdfProperties, Reciprocity) {
  BsdfKernels& k = bsdf_kernels();
  const size_t n = 4000;
  for (const Named& c : non_delta_materials()) {
    SCOPED_TRACE(c.name);
    bool sphere = c.m.type == BSDF_ROUGH_DIELECTRIC;
    std::vector<cl_float4> a = random_dirs(n, 11, !sphere), b = random_dirs(n, 12, !sphere);
    std::vector<cl_float4> fab = k.eval(c.m, a, b), fba = k.eval(c.m, b, a);
    const double eta = c.m.eta[0];
    size_t nonzero = 0, loose = 0;
    for (size_t i = 0; i < n; ++i) {
      double ca = std::fabs(a[i].s[2]), cb = std::fabs(b[i].s[2]);
      if (ca < 1e-3 || cb < 1e-3) continue;
      double eta_a = a[i].s[2] > 0 ? 1.0 : eta, eta_b = b[i].s[2] > 0 ? 1.0 : eta;
      for (int ch = 0; ch < 3; ++ch) {
        double f1 = fab[i].s[ch] / cb * eta_b * eta_b, f2 = fba[i].s[ch] / ca * eta_a * eta_a;
        if (f1 > 0 || f2 > 0) ++nonzero;
        // Values below 1e-4 (far tails, where D itself is a few ulps) compare absolutely.
        if (rel_diff(f1, f2, 1e-4) > 2e-3) ++loose;
      }
    }
    EXPECT_GT(nonzero, n / 4);
    // Float rounding of the half vector is amplified near the critical angle, where 1 - F
    // varies like the square root of the distance to it: allow rare outliers there.
    EXPECT_LE(loose, nonzero / 200) << loose << " of " << nonzero;
  }
}

struct Albedo {
  double mean = 0.0, std_error = 0.0;
};

// Mean of the sampling weight (importance form: times eta^2 after refraction), all lobes.
Albedo albedo(const GdrMaterial& m, double cos_wo, unsigned seed, unsigned n) {
  SampleBatch s = bsdf_kernels().sample_rng(m, dir_cos(cos_wo, 0.9), seed, n);
  double sum = 0.0, sum2 = 0.0;
  for (unsigned i = 0; i < n; ++i) {
    double eta = s.weight_eta[i].s[3];
    double w = s.flags[i].s[0] ? (s.weight_eta[i].s[0] + s.weight_eta[i].s[1] +
                                  s.weight_eta[i].s[2]) / 3.0 * eta * eta
                               : 0.0;
    sum += w;
    sum2 += w * w;
  }
  Albedo a;
  a.mean = sum / n;
  a.std_error = std::sqrt(std::max(0.0, sum2 / n - a.mean * a.mean) / n);
  return a;
}

// White furnace: no BSDF with white reflectances reflects + transmits more than it receives.
// 2^16 samples per (material, wo), seeds 100+; bound: 1 + 5 standard errors (false-positive
// rate < 3e-7 per check) + the documented approximation error of the plastics' internal
// reflectance (fit / quadrature: 2e-3).
TEST(BsdfEnergy, WhiteAlbedoAtMostOne) {
  GdrMaterial mirror_rough = mirror_material(BSDF_ROUGH_CONDUCTOR);
  mirror_rough.alpha_u = mirror_rough.alpha_v = 0.5f;
  std::vector<Named> mats = {
      {"rough_mirror_ggx", mirror_rough},
      {"rough_conductor_beckmann",
       conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_BECKMANN, 0.8f, 0.8f)},
      {"rough_dielectric_ggx", dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_GGX, 0.5f)},
      {"rough_dielectric_beckmann",
       dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_BECKMANN, 0.1f)},
      {"plastic", plastic_material(BSDF_PLASTIC, 1.5f, 1.0f)},
      {"plastic_nonlinear", plastic_material(BSDF_PLASTIC, 1.5f, 1.0f, 1)},
      {"rough_plastic_ggx", plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 1.0f, 0, MICROFACET_GGX, 0.8f)},
      {"rough_plastic_ggx_smooth",
       plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 1.0f, 0, MICROFACET_GGX, 0.05f)},
      {"rough_plastic_beckmann",
       plastic_material(BSDF_ROUGH_PLASTIC, 1.7f, 1.0f, 1, MICROFACET_BECKMANN, 0.5f)},
      {"thin_dielectric", dielectric_material(BSDF_THIN_DIELECTRIC, 1.5f)},
  };
  unsigned seed = 100;
  for (const Named& c : mats) {
    for (double cw : {1.0, 0.5, 0.1, -0.5}) {
      if (cw < 0 && !two_sided_transport(c.m)) continue;
      Albedo a = albedo(c.m, cw, seed++, 1u << 16);
      if (getenv("GDR_PRINT_ALBEDO")) printf("%s %g: %.5f +- %.5f\n", c.name.c_str(), cw, a.mean, a.std_error);
      EXPECT_LE(a.mean, 1.0 + 5 * a.std_error + 2e-3) << c.name << " cos(wo) " << cw;
      EXPECT_GT(a.mean, 0.0) << c.name;
    }
  }
}

// Lambertian white reflects everything: every sample carries weight exactly 1.
TEST(BsdfEnergy, WhiteDiffuseAlbedoIsOne) {
  for (double cw : {1.0, 0.3, 0.01}) {
    Albedo a = albedo(diffuse_material(1.0f), cw, 200, 1u << 18);
    EXPECT_NEAR(a.mean, 1.0, 1e-4) << cw;
  }
}

// The "none" conductor (eta = 0) and the rough dielectric's and smooth dielectric's lobes.
TEST(BsdfEnergy, MirrorReflectsExactlyOne) {
  SampleBatch s = bsdf_kernels().sample(mirror_material(), random_dirs(1000, 3, true),
                                        random_dirs(1000, 4, true));
  for (size_t i = 0; i < 1000; ++i) {
    ASSERT_TRUE(s.flags[i].s[0]);
    EXPECT_EQ(s.flags[i].s[1], 1);
    for (int ch = 0; ch < 3; ++ch) EXPECT_FLOAT_EQ(s.weight_eta[i].s[ch], 1.0f);
  }
}

// Smooth dielectric: the two lobes' probabilities sum to 1 and each carries weight 1 in the
// importance form (R + T = 1 for every wo).
TEST(BsdfEnergy, SmoothDielectricReflectPlusTransmitIsOne) {
  BsdfKernels& k = bsdf_kernels();
  for (float eta : {1.5f, 1.0f / 1.33f}) {
    GdrMaterial m = dielectric_material(BSDF_DIELECTRIC, eta);
    for (double cw : {1.0, 0.7, 0.2, -0.3, -0.9}) {
      cl_float4 wo = dir_cos(cw, 0.4);
      SampleBatch s = k.sample(m, {wo, wo}, {f4(0.0f, 0.5f, 0.5f), f4(0.999999f, 0.5f, 0.5f)});
      ASSERT_TRUE(s.flags[0].s[0]);
      double r = s.wi_pdf[0].s[3];
      double t = s.flags[1].s[2] ? s.wi_pdf[1].s[3] : 0.0;  // total internal reflection: no T
      if (!s.flags[1].s[2]) EXPECT_DOUBLE_EQ(r, 1.0);
      EXPECT_NEAR(r + t, 1.0, 1e-6) << eta << " " << cw;
      for (int i = 0; i < 2; ++i) {
        if (!s.flags[i].s[0]) continue;
        double e = s.weight_eta[i].s[3];
        EXPECT_NEAR(s.weight_eta[i].s[0] * e * e, 1.0, 1e-5);
      }
    }
  }
}

cl_float4 snell(cl_float4 wo, double eta) {
  double sin_t = std::sqrt(1 - wo.s[2] * wo.s[2]) / eta;
  double phi = std::atan2(wo.s[1], wo.s[0]) + M_PI;
  cl_float4 d = dir_cos(std::sqrt(1 - sin_t * sin_t), phi);
  d.s[2] = -d.s[2];
  return d;
}

TEST(BsdfDelta, ConductorMirrorsWithComplexFresnel) {
  BsdfKernels& k = bsdf_kernels();
  GdrMaterial m = conductor_material(BSDF_CONDUCTOR);
  cl_float4 wo = dir_cos(1.0, 0.0), wo2 = dir_cos(0.6, 1.2);
  SampleBatch s = k.sample(m, {wo, wo2}, {f4(0.3f, 0.3f, 0.3f), f4(0.7f, 0.1f, 0.9f)});
  ASSERT_TRUE(s.flags[0].s[0] && s.flags[1].s[0]);
  EXPECT_EQ(s.flags[1].s[1], 1);
  EXPECT_FLOAT_EQ(s.wi_pdf[1].s[0], -wo2.s[0]);
  EXPECT_FLOAT_EQ(s.wi_pdf[1].s[1], -wo2.s[1]);
  EXPECT_FLOAT_EQ(s.wi_pdf[1].s[2], wo2.s[2]);
  // Normal incidence: ((n - 1)^2 + k^2) / ((n + 1)^2 + k^2) per channel.
  for (int ch = 0; ch < 3; ++ch) {
    double n = m.eta[ch], kk = m.k[ch];
    double f = ((n - 1) * (n - 1) + kk * kk) / ((n + 1) * (n + 1) + kk * kk);
    EXPECT_NEAR(s.weight_eta[0].s[ch], f, 1e-5) << ch;
  }
  // Delta BSDFs have no eval / pdf.
  std::vector<cl_float4> ev = k.eval(m, {wo2}, {s.wi_pdf[1]});
  EXPECT_EQ(ev[0].s[0], 0.0f);
  EXPECT_EQ(ev[0].s[3], 0.0f);
}

TEST(BsdfDelta, DielectricSnellFresnelAndTotalInternalReflection) {
  BsdfKernels& k = bsdf_kernels();
  GdrMaterial m = dielectric_material(BSDF_DIELECTRIC, 1.5f);
  cl_float4 n = dir_cos(1.0, 0.0), oblique = dir_cos(0.5, 0.8), inside = dir_cos(-0.9, 2.0);
  cl_float4 tir = dir_cos(-0.5, 2.0);  // sin 0.866 > 1 / 1.5: beyond the critical angle
  std::vector<cl_float4> wo = {n, n, oblique, inside, tir, tir};
  std::vector<cl_float4> u = {f4(0.01f, 0, 0), f4(0.5f, 0, 0), f4(0.99f, 0, 0),
                              f4(0.99f, 0, 0), f4(0.0f, 0, 0), f4(0.999f, 0, 0)};
  SampleBatch s = k.sample(m, wo, u);
  for (size_t i = 0; i < wo.size(); ++i) ASSERT_TRUE(s.flags[i].s[0]) << i;
  // Normal incidence: R = ((eta - 1) / (eta + 1))^2 = 0.04.
  EXPECT_EQ(s.flags[0].s[2], 0);
  EXPECT_NEAR(s.wi_pdf[0].s[3], 0.04, 1e-6);
  EXPECT_EQ(s.flags[1].s[2], 1);
  EXPECT_NEAR(s.wi_pdf[1].s[3], 0.96, 1e-6);
  EXPECT_NEAR(s.wi_pdf[1].s[2], -1.0, 1e-6);
  EXPECT_NEAR(s.weight_eta[1].s[3], 1.5, 1e-6);
  // Oblique refraction follows Snell's law; from inside, eta is inverted.
  for (int i : {2, 3}) {
    ASSERT_EQ(s.flags[i].s[2], 1) << i;
    double eta = wo[i].s[2] > 0 ? 1.5 : 1 / 1.5;
    cl_float4 expect = snell(wo[i], eta);
    if (wo[i].s[2] < 0) expect.s[2] = -expect.s[2];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.wi_pdf[i].s[c], expect.s[c], 1e-5) << i << " " << c;
    EXPECT_NEAR(s.weight_eta[i].s[3], eta, 1e-6);
  }
  for (int i : {4, 5}) {
    EXPECT_EQ(s.flags[i].s[2], 0) << "total internal reflection transmits nothing";
    EXPECT_FLOAT_EQ(s.wi_pdf[i].s[3], 1.0f);
    EXPECT_FLOAT_EQ(s.wi_pdf[i].s[2], tir.s[2]);
  }
}

TEST(BsdfDelta, ThinDielectricAndIndexMatchedPassStraightThrough) {
  BsdfKernels& k = bsdf_kernels();
  cl_float4 wo = dir_cos(1.0, 0.0), wo2 = dir_cos(0.4, 2.5);
  SampleBatch s = k.sample(dielectric_material(BSDF_THIN_DIELECTRIC, 1.5f), {wo, wo2},
                           {f4(0.0f, 0, 0), f4(0.99f, 0, 0)});
  // Normal incidence with inter-reflections: 2R / (1 + R), R = 0.04.
  EXPECT_NEAR(s.wi_pdf[0].s[3], 0.08 / 1.04, 1e-6);
  EXPECT_EQ(s.flags[1].s[2], 1);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(s.wi_pdf[1].s[c], -wo2.s[c]);
  for (int type : {BSDF_DIELECTRIC, BSDF_ROUGH_DIELECTRIC}) {
    SampleBatch m = k.sample(dielectric_material(type, 1.0f, MICROFACET_GGX, 0.3f), {wo2},
                             {f4(0.01f, 0.3f, 0.6f)});
    ASSERT_TRUE(m.flags[0].s[0]) << type;
    EXPECT_EQ(m.flags[0].s[1], 1) << "index-matched interfaces are a delta transmission";
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(m.wi_pdf[0].s[c], -wo2.s[c], 1e-6);
    EXPECT_NEAR(m.weight_eta[0].s[0], 1.0, 1e-6);
  }
}

TEST(BsdfDelta, PlasticCoatingMirrors) {
  BsdfKernels& k = bsdf_kernels();
  cl_float4 wo = dir_cos(0.3, 1.0);
  SampleBatch s = k.sample(plastic_material(BSDF_PLASTIC, 1.5f, 0.5f), {wo}, {f4(0.0f, 0.5f, 0.5f)});
  ASSERT_TRUE(s.flags[0].s[0]);
  EXPECT_EQ(s.flags[0].s[1], 1);
  EXPECT_FLOAT_EQ(s.wi_pdf[0].s[0], -wo.s[0]);
  EXPECT_FLOAT_EQ(s.wi_pdf[0].s[2], wo.s[2]);
}

TEST(BsdfInfo, RoughnessClassification) {
  BsdfKernels& k = bsdf_kernels();
  cl_float4 d = k.info(diffuse_material());
  EXPECT_GE(d.s[0], 1.0f);
  EXPECT_EQ(d.s[1], 0.0f);
  EXPECT_EQ(d.s[2], 1.0f);
  cl_float4 c = k.info(conductor_material(BSDF_CONDUCTOR));
  EXPECT_EQ(c.s[0], 0.0f);
  EXPECT_EQ(c.s[1], 1.0f);
  cl_float4 r = k.info(conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_GGX, 0.3f, 0.05f));
  EXPECT_FLOAT_EQ(r.s[0], 0.05f);
  EXPECT_EQ(r.s[1], 0.0f);
  cl_float4 tiny = k.info(conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_GGX, 0.0f, 0.0f));
  EXPECT_FLOAT_EQ(tiny.s[0], 1e-4f) << "alpha is clamped to its minimum";
  cl_float4 p = k.info(plastic_material(BSDF_PLASTIC, 1.5f, 0.5f));
  EXPECT_EQ(p.s[0], 0.0f);
  EXPECT_EQ(p.s[1], 0.0f);
  EXPECT_EQ(p.s[2], 1.0f);
  EXPECT_EQ(p.s[3], 1.0f);
  cl_float4 rp = k.info(plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 0.5f, 0, MICROFACET_GGX, 0.2f));
  EXPECT_FLOAT_EQ(rp.s[0], 0.2f);
  EXPECT_EQ(rp.s[2], 1.0f);
  EXPECT_EQ(rp.s[3], 0.0f);
  EXPECT_EQ(k.info(dielectric_material(BSDF_THIN_DIELECTRIC, 1.5f)).s[1], 1.0f);
}

// The half vector helpers: the refraction half vector of a Snell pair is the normal, its
// reflection counterpart bisects, and index-matched straight transmission reports failure.
TEST(BsdfHalfVector, RefractionHalfVectorOfSnellPairIsTheNormal) {
  BsdfKernels& k = bsdf_kernels();
  cl_float4 wo = dir_cos(0.6, 0.7);
  cl_float4 wt = snell(wo, 1.5);
  std::vector<cl_float4> a = {wo, wo, wo}, b = {wt, dir_cos(0.8, 2.0), f4(-wo.s[0], -wo.s[1], -wo.s[2])};
  for (float eta : {1.5f, 1.0f}) {
    Buffer<cl_float4> ab(k.context(), a), bb(k.context(), b), h(k.context(), 3);
    Buffer<float> jac(k.context(), 3);
    k.program()->kernel("bsdf_half_vector_batch").args(ab, bb, eta, 3u, h, jac).run(3);
    std::vector<cl_float4> hv = h.read();
    std::vector<float> j = jac.read();
    if (eta == 1.5f) {
      EXPECT_NEAR(hv[0].s[2], 1.0, 1e-5);
      EXPECT_EQ(hv[0].s[3], 1.0f);
      EXPECT_GT(j[0], 0.0f);
      EXPECT_TRUE(std::isfinite(j[0]));
      // reflection: the bisector, Jacobian 1 / (4 wi.h)
      double hx = wo.s[0] + b[1].s[0], hy = wo.s[1] + b[1].s[1], hz = wo.s[2] + b[1].s[2];
      double len = std::sqrt(hx * hx + hy * hy + hz * hz);
      EXPECT_NEAR(hv[1].s[2], hz / len, 1e-5);
      double wih = (b[1].s[0] * hx + b[1].s[1] * hy + b[1].s[2] * hz) / len;
      EXPECT_NEAR(j[1], 1.0 / (4 * wih), 1e-4);
    } else {
      EXPECT_EQ(hv[2].s[3], 0.0f) << "wi == -wo with eta 1 has no half vector";
      EXPECT_EQ(j[2], 0.0f);
    }
  }
}

}  // namespace
}  // namespace gdr::test
