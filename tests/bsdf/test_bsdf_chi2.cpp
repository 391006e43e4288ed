// Chi-square goodness-of-fit of every non-delta BSDF's sampling against its own pdf (the test
// pbrt and Mitsuba use). For each case, 10^6 samples (seed = 1000 + case index, the engine's
// Philox RNG) are binned on a 10 (theta) x 20 (phi) grid over the whole sphere; one more cell
// holds the samples that produced nothing or a delta lobe. Expected counts integrate bsdf_pdf
// (evaluated by the kernel) over each cell with composite 3-point Gauss-Legendre rules (10 x 10
// sub-intervals per cell, 30 x 30 for the narrow lobes of alpha <= 0.1, never on a cell edge, where the pdf may jump). Cells expected < 5 are
// pooled. Family-wise false-positive rate 1e-3 over all cases (Sidak-corrected per case).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "bsdf/bsdf_harness.h"
#include "bsdf/chi2.h"

namespace gdr::test {
namespace {

constexpr int kThetaBins = 10, kPhiBins = 20;
constexpr unsigned kSamples = 1000000;
constexpr double kFamilyAlpha = 1e-3;

struct Chi2Case {
  std::string name;
  GdrMaterial material;
  double cos_wo;
  double phi_wo;
};

std::vector<Chi2Case> make_cases() {
  std::vector<Chi2Case> c;
  c.push_back({"Diffuse_Normal", diffuse_material(0.7f), 0.8, 0.3});
  c.push_back({"Diffuse_Grazing", diffuse_material(0.7f), 0.02, 1.0});
  GdrMaterial two = diffuse_material(0.7f);
  two.twosided = 1;
  c.push_back({"Diffuse_TwoSidedBack", two, -0.6, 2.0});

  const char* dist_name[2] = {"Beckmann", "GGX"};
  const float aniso[5][2] = {{0.05f, 0.05f}, {0.3f, 0.3f}, {0.8f, 0.8f}, {0.05f, 0.3f},
                             {0.8f, 0.2f}};
  for (int d = 0; d < 2; ++d) {
    for (const auto& a : aniso) {
      GdrMaterial m = conductor_material(BSDF_ROUGH_CONDUCTOR, d, a[0], a[1]);
      std::ostringstream n;
      n << "RoughConductor_" << dist_name[d] << "_" << int(a[0] * 100) << "_" << int(a[1] * 100);
      c.push_back({n.str() + "_Mid", m, 0.7, 0.4});
      c.push_back({n.str() + "_Grazing", m, 0.1, 2.2});
    }
  }

  // Rough dielectrics: both sides of the interface, eta and its inverse.
  for (int d = 0; d < 2; ++d) {
    for (float eta : {1.5f, 1.0f / 1.5f}) {
      for (double side : {1.0, -1.0}) {
        std::ostringstream n;
        n << "RoughDielectric_" << dist_name[d] << "_eta" << (eta > 1 ? "1.5" : "0.67")
          << (side > 0 ? "_Outside" : "_Inside");
        c.push_back({n.str(), dielectric_material(BSDF_ROUGH_DIELECTRIC, eta, d, 0.3f),
                     0.5 * side, 0.7});
      }
    }
  }
  c.push_back({"RoughDielectric_GGX_Smooth_Outside",
               dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_GGX, 0.08f), 0.9, 0.1});
  c.push_back({"RoughDielectric_GGX_Smooth_InsideGrazing",
               dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_GGX, 0.08f), -0.2, 1.1});
  c.push_back({"RoughDielectric_Beckmann_Rough_Grazing",
               dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_BECKMANN, 0.8f), 0.1,
               3.0});
  c.push_back({"RoughDielectric_Beckmann_Rough_Inside",
               dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_BECKMANN, 0.8f), -0.7,
               5.0});
  GdrMaterial an = dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_GGX, 0.1f);
  an.alpha_v = 0.4f;
  c.push_back({"RoughDielectric_GGX_Anisotropic", an, 0.6, 0.8});

  c.push_back({"RoughPlastic_GGX_Mid",
               plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 0.5f, 0, MICROFACET_GGX, 0.15f), 0.7, 0.2});
  c.push_back({"RoughPlastic_GGX_Grazing",
               plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 0.5f, 0, MICROFACET_GGX, 0.15f), 0.1, 0.2});
  c.push_back({"RoughPlastic_Beckmann",
               plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 0.8f, 0, MICROFACET_BECKMANN, 0.4f), 0.5,
               4.0});
  c.push_back({"RoughPlastic_Nonlinear",
               plastic_material(BSDF_ROUGH_PLASTIC, 1.33f, 0.3f, 1, MICROFACET_GGX, 0.3f), 0.3, 1.5});
  c.push_back({"Plastic_Mid", plastic_material(BSDF_PLASTIC, 1.5f, 0.5f), 0.8, 0.0});
  c.push_back({"Plastic_Grazing", plastic_material(BSDF_PLASTIC, 1.5f, 0.5f), 0.05, 0.0});
  return c;
}

const std::vector<Chi2Case>& cases() {
  static const std::vector<Chi2Case> c = make_cases();
  return c;
}

// Composite 3-point Gauss-Legendre nodes and weights over [0, range) split into bins * sub
// sub-intervals.
void gauss_nodes(double range, int bins, int sub, std::vector<float>& x, std::vector<double>& w) {
  const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double gw[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  double h = range / (bins * sub);
  for (int i = 0; i < bins * sub; ++i) {
    for (int k = 0; k < 3; ++k) {
      x.push_back(float((i + 0.5 + 0.5 * g[k]) * h));
      w.push_back(0.5 * h * gw[k]);
    }
  }
}

class BsdfChi2 : public testing::TestWithParam<size_t> {};

TEST_P(BsdfChi2, SamplingMatchesPdf) {
  const Chi2Case& c = cases()[GetParam()];
  BsdfKernels& k = bsdf_kernels();
  cl_float4 wo = dir_cos(c.cos_wo, c.phi_wo);
  const int cells = kThetaBins * kPhiBins;

  SampleBatch s = k.sample_rng(c.material, wo, 1000u + unsigned(GetParam()), kSamples);
  std::vector<double> observed(cells + 1, 0.0);
  for (unsigned i = 0; i < kSamples; ++i) {
    if (!s.flags[i].s[0] || s.flags[i].s[1]) {
      observed[cells] += 1.0;  // no sample, or a delta lobe (outside bsdf_pdf)
      continue;
    }
    const cl_float4& w = s.wi_pdf[i];
    double theta = std::acos(std::clamp(double(w.s[2]), -1.0, 1.0));
    double phi = std::atan2(double(w.s[1]), double(w.s[0]));
    if (phi < 0) phi += 2 * M_PI;
    int bt = std::min(kThetaBins - 1, int(theta / M_PI * kThetaBins));
    int bp = std::min(kPhiBins - 1, int(phi / (2 * M_PI) * kPhiBins));
    observed[bt * kPhiBins + bp] += 1.0;
  }

  std::vector<float> theta, phi;
  std::vector<double> wt, wp;
  const int sub = std::min(c.material.alpha_u, c.material.alpha_v) <= 0.1f ? 30 : 10;
  gauss_nodes(M_PI, kThetaBins, sub, theta, wt);
  gauss_nodes(2 * M_PI, kPhiBins, sub, phi, wp);
  std::vector<float> pdf = k.pdf_grid(c.material, wo, theta, phi);
  std::vector<double> expected(cells + 1, 0.0);
  const int per_t = sub * 3, np = int(phi.size());
  double total = 0.0;
  for (size_t it = 0; it < theta.size(); ++it) {
    double st = std::sin(double(theta[it])) * wt[it];
    int bt = int(it) / per_t;
    for (int ip = 0; ip < np; ++ip) {
      double v = double(pdf[it * np + ip]) * st * wp[ip] * kSamples;
      expected[bt * kPhiBins + ip / per_t] += v;
      total += v;
    }
  }
  // The pdf of sampled directions integrates to at most 1 (integration error is ~1e-5).
  ASSERT_LE(total, kSamples * (1.0 + 1e-3)) << c.name;
  expected[cells] = std::max(0.0, kSamples - total);

  Chi2Result r = chi2_test(observed, expected, kSamples);
  std::ostringstream worst;  // the most deviant cells, for the failure message
  for (int i = 0; i <= cells; ++i) {
    double z = (observed[i] - expected[i]) / std::sqrt(std::max(expected[i], 1.0));
    if (std::fabs(z) > 4) {
      worst << "\n  cell theta " << i / kPhiBins << " phi " << i % kPhiBins << ": observed "
            << observed[i] << ", expected " << expected[i];
    }
  }
  const double alpha = 1.0 - std::pow(1.0 - kFamilyAlpha, 1.0 / double(cases().size()));
  EXPECT_TRUE(r.error.empty()) << c.name << ": " << r.error;
  EXPECT_GT(r.p_value, alpha) << c.name << ": chi2 = " << r.statistic << ", dof = " << r.dof
                              << ", p = " << r.p_value << ", sampled mass "
                              << (kSamples - observed[cells]) / kSamples << " vs pdf mass "
                              << total / kSamples << worst.str();
}

INSTANTIATE_TEST_SUITE_P(AllNonDelta, BsdfChi2, testing::Range(size_t(0), cases().size()),
                         [](const testing::TestParamInfo<size_t>& info) {
                           std::string n = cases()[info.param].name;
                           for (char& ch : n) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return n;
                         });

}  // namespace
}  // namespace gdr::test
