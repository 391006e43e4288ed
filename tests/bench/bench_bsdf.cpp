// bsdf_sample throughput per BSDF family on the default device (items/s), 2^20 samples at one
// oblique wo, uniforms from the engine's RNG.
#include <benchmark/benchmark.h>

#include <vector>

#include "bsdf/bsdf_harness.h"

namespace gdr {
namespace {

GdrMaterial bench_material(int family) {
  using namespace test;
  switch (family) {
    case 0: return diffuse_material(0.8f);
    case 1: return conductor_material(BSDF_CONDUCTOR);
    case 2: return conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_GGX, 0.2f, 0.2f);
    case 3: return conductor_material(BSDF_ROUGH_CONDUCTOR, MICROFACET_BECKMANN, 0.2f, 0.2f);
    case 4: return dielectric_material(BSDF_DIELECTRIC, 1.5f);
    case 5: return dielectric_material(BSDF_THIN_DIELECTRIC, 1.5f);
    case 6: return dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_GGX, 0.2f);
    case 7: return dielectric_material(BSDF_ROUGH_DIELECTRIC, 1.5f, MICROFACET_BECKMANN, 0.2f);
    case 8: return plastic_material(BSDF_PLASTIC, 1.5f, 0.5f);
    default: return plastic_material(BSDF_ROUGH_PLASTIC, 1.5f, 0.5f, 0, MICROFACET_GGX, 0.2f);
  }
}

const char* kNames[] = {"diffuse",          "conductor",         "roughconductor_ggx",
                        "roughconductor_beckmann", "dielectric",  "thindielectric",
                        "roughdielectric_ggx",     "roughdielectric_beckmann", "plastic",
                        "roughplastic_ggx"};

void BM_BsdfSample(benchmark::State& state) {
  test::BsdfKernels& k = test::bsdf_kernels();
  Context& ctx = k.context();
  const int family = static_cast<int>(state.range(0));
  const unsigned count = 1u << 20;
  GdrMaterial m = bench_material(family);
  test::DeviceMaterial mat = k.upload(m);
  Buffer<float> out(ctx, count);
  Kernel kernel = k.program()->kernel("bsdf_sample_bench");
  kernel.args(mat.material, mat.coating_tables, test::reflectance_of(m), test::dir_cos(0.6, 0.3), 1u, count, out);
  kernel.run(count);  // PoCL compiles the work-group function at the first launch
  for (auto _ : state) kernel.run(count);
  state.SetItemsProcessed(int64_t(state.iterations()) * count);
  state.SetLabel(std::string(kNames[family]) + " on " + ctx.device().name);
}
BENCHMARK(BM_BsdfSample)->DenseRange(0, 9)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gdr
