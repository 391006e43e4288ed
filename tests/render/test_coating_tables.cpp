// The plastics' coating tables (render/coating_tables.h, kernels/bsdf/coating_tables.cl): laid
// out as kernels/shared/coating_table.h says, built only for the plastics a scene uses, and
// holding what an independent integral of the model (tests/bsdf/coating_reference.h) gives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bsdf/coating_reference.h"
#include "render/coating_tables.h"
#include "render/device_scene.h"
#include "shared/coating_table.h"
#include "support/devices.h"
#include "support/envmap_scene.h"

namespace gdr {
namespace {

namespace cr = test::coating;

GdrMaterial plastic(int type, int distribution, float alpha, float eta) {
  GdrMaterial m{};
  m.type = type;
  m.distribution = distribution;
  m.alpha_u = m.alpha_v = alpha;
  m.eta[0] = m.eta[1] = m.eta[2] = eta;
  m.reflectance[0] = m.reflectance[1] = m.reflectance[2] = 0.5f;
  m.specular_reflectance[0] = m.specular_reflectance[1] = m.specular_reflectance[2] = 1.0f;
  m.reflectance_texture = -1;
  m.coating_table = -1;
  return m;
}

std::vector<float> table_of(const GdrMaterial& m) {
  std::vector<GdrMaterial> one{m};
  std::vector<float> tables;
  build_coating_tables(test::default_context(), one, tables);
  EXPECT_EQ(one[0].coating_table, 0);
  return tables;
}

// Offsets in material order, each coating once.
TEST(CoatingTables, EachPlasticCoatingGetsOneBlockOthersNone) {
  std::vector<GdrMaterial> m = {plastic(BSDF_DIFFUSE, MICROFACET_GGX, 0.1f, 1.0f),
                                plastic(BSDF_ROUGH_PLASTIC, MICROFACET_GGX, 0.1f, 1.5f),
                                plastic(BSDF_PLASTIC, MICROFACET_GGX, 0.0f, 1.5f),
                                plastic(BSDF_ROUGH_CONDUCTOR, MICROFACET_GGX, 0.1f, 1.0f),
                                plastic(BSDF_ROUGH_PLASTIC, MICROFACET_BECKMANN, 0.3f, 1.9f)};
  // The same coating in another colour, nonlinear: it shares the block of m[1].
  m.push_back(m[1]);
  m.back().reflectance[1] = 0.9f;
  m.back().nonlinear = 1;
  m[0].coating_table = 7;  // stale offsets are replaced
  std::vector<float> tables;
  build_coating_tables(test::default_context(), m, tables, {true, true, true, true, true, true});
  EXPECT_EQ(m[0].coating_table, -1);
  EXPECT_EQ(m[1].coating_table, 0);
  EXPECT_EQ(m[2].coating_table, 1 + GDR_COATING_NODES);
  EXPECT_EQ(m[3].coating_table, -1);
  EXPECT_EQ(m[4].coating_table, 2 + GDR_COATING_NODES);
  EXPECT_EQ(m[5].coating_table, m[1].coating_table);
  ASSERT_EQ(tables.size(), size_t(3 + 2 * GDR_COATING_NODES));
  // Blocks are the materials' own: the same material alone gives the same table.
  std::vector<float> alone = table_of(m[4]);
  for (size_t i = 0; i < alone.size(); ++i) EXPECT_EQ(tables[m[4].coating_table + i], alone[i]) << i;
}

// Principle 3: a scene without a plastic shape builds and launches nothing for them; the same
// scene with a rough plastic ground does (so the check can fail).
TEST(CoatingTables, BuiltOnlyForPlasticsTheSceneUses) {
  auto launches = [](const Scene& scene) {
    Stats stats;
    Context ctx(select_device(""), &stats);
    DeviceScene device(ctx, scene);
    return stats.count("kernel_items/coating_partial_sums");
  };
  Scene scene = test::envmap_scene();
  for (const GdrMaterial& m : scene.materials) ASSERT_EQ(coating_table_size(m.type), 0);
  // A plastic that no shape uses costs nothing either.
  scene.materials.push_back(plastic(BSDF_ROUGH_PLASTIC, MICROFACET_GGX, 0.2f, 1.5f));
  scene.material_names.push_back("unused plastic");
  EXPECT_EQ(launches(scene), 0u);
  scene.shapes.back().material = static_cast<int>(scene.materials.size() - 1);
  EXPECT_GT(launches(scene), 0u);
}

// Mitsuba's smooth plastic: R_int is the diffuse Fresnel reflectance fit (Egan & Hilgeman for
// light inside, relative IOR 1 / eta), within 1% of the exact hemispherical integral of the
// Fresnel reflectance, 2 int F(mu) mu dmu (this file's Fresnel, 4000-node Gauss-Legendre split
// at the critical angle; the fit's stated error is below 0.6% for IORs up to 2).
TEST(CoatingTables, SmoothCoatingInternalReflectanceIsTheDiffuseFresnelReflectance) {
  for (float eta : {1.33f, 1.5f, 1.9f}) {
    std::vector<float> t = table_of(plastic(BSDF_PLASTIC, MICROFACET_GGX, 0.0f, eta));
    ASSERT_EQ(t.size(), 1u);
    double critical = std::sqrt(1 - 1 / (double(eta) * eta)), exact = 0;
    for (auto [a, b] : {std::pair<double, double>{0, critical}, {critical, 1}}) {
      GaussLegendre g = gauss_legendre(1000, a, b);
      for (int i = 0; i < 1000; ++i) {
        double ct = 0;
        exact += 2 * g.weights[i] * g.nodes[i] * cr::fresnel(g.nodes[i], 1 / double(eta), &ct);
      }
    }
    EXPECT_NEAR(t[GDR_COATING_INTERNAL_REFLECTANCE] / exact, 1.0, 1e-2) << eta;
  }
}

// The rough coating's table against the reference model at its own nodes: transmittance within
// 1e-3 at every cosine from 1/63 up, R_int (by the same 64-node rule as Mitsuba on both sides)
// within 3e-4. The table's 32 x 32 Gauss-Legendre rule over the visible normals is the larger
// error (measured up to 3e-4 in t, 4e-5 in R_int); the reference is converged to 6e-5. An alpha
// of 1e-4 is the smooth coating: t = 1 - F.
TEST(CoatingTables, RoughCoatingMatchesTheReferenceModel) {
  struct Case {
    int distribution;
    float alpha, eta;
  };
  for (Case c : {Case{MICROFACET_GGX, 0.01f, 1.5f}, Case{MICROFACET_GGX, 0.1f, 1.5f},
                 Case{MICROFACET_GGX, 0.5f, 1.33f}, Case{MICROFACET_BECKMANN, 0.3f, 1.9f},
                 Case{MICROFACET_BECKMANN, 1e-4f, 1.5f}}) {
    SCOPED_TRACE("distribution " + std::to_string(c.distribution) + " alpha " +
                 std::to_string(c.alpha) + " eta " + std::to_string(c.eta));
    std::vector<float> t = table_of(plastic(BSDF_ROUGH_PLASTIC, c.distribution, c.alpha, c.eta));
    ASSERT_EQ(t.size(), size_t(1 + GDR_COATING_NODES));
    cr::Model md{c.distribution == MICROFACET_BECKMANN, c.alpha, c.eta};
    cr::Normals nn = cr::normal_nodes(md, 128);
    double worst = 0;
    for (int i = 1; i < GDR_COATING_NODES; ++i) {
      double mu = i / 63.0, want = cr::transmittance(md, nn, mu);
      if (c.alpha < 1e-3f) {
        double ct = 0;
        want = 1 - cr::fresnel(mu, c.eta, &ct);
      }
      EXPECT_NEAR(t[GDR_COATING_TRANSMITTANCE + i], want, 1e-3) << "cos " << mu;
      worst = std::fmax(worst, std::fabs(t[GDR_COATING_TRANSMITTANCE + i] - want));
    }
    double r_int = cr::internal_reflectance(md, nn);
    EXPECT_NEAR(t[GDR_COATING_INTERNAL_REFLECTANCE], r_int, 3e-4);
    if (getenv("GDR_PRINT_COATING")) {
      std::printf("t: largest difference %.2e; R_int %.6f, reference %.6f\n", worst,
                  t[GDR_COATING_INTERNAL_REFLECTANCE], r_int);
    }
  }
}

}  // namespace
}  // namespace gdr
