// What PoCL's vectorizer needs, on one diffuse bounce's sampling (kernels/tests/vectorization_probe.cl):
// the engine's float3 form, the same numbers as scalar structure-of-arrays code, and eight items a
// work item in float8 values; items/s for 2^20 items. The binary first checks once that every form
// gives the float3 form's directions and throughputs (to 1e-4), so the figures compare the same work.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "device/context.h"
#include "support/devices.h"

namespace gdr {
namespace {

constexpr unsigned kCount = 1u << 20;
constexpr unsigned kSeed = 7u;

struct ProbeBuffers {
  Buffer<cl_float4> normal, throughput, dir, throughput_out;
  Buffer<float> in, out, out_lanes;  // component-major: component c of item i at c * kCount + i
};

ProbeBuffers& probe_buffers() {
  static ProbeBuffers* b = [] {
    Context& ctx = test::default_context();
    std::mt19937 rng(12345);
    std::normal_distribution<float> gauss;
    std::uniform_real_distribution<float> unit(0.1f, 2.0f);
    std::vector<cl_float4> normal(kCount), throughput(kCount);
    std::vector<float> in(6 * size_t(kCount));
    for (unsigned i = 0; i < kCount; ++i) {
      float v[3] = {gauss(rng), gauss(rng), gauss(rng)};
      float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      float t[3] = {unit(rng), unit(rng), unit(rng)};
      for (int c = 0; c < 3; ++c) {
        normal[i].s[c] = v[c] / len;
        throughput[i].s[c] = t[c];
        in[c * size_t(kCount) + i] = v[c] / len;
        in[(3 + c) * size_t(kCount) + i] = t[c];
      }
      normal[i].s[3] = throughput[i].s[3] = 0.0f;
    }
    return new ProbeBuffers{Buffer<cl_float4>(ctx, normal), Buffer<cl_float4>(ctx, throughput),
                            Buffer<cl_float4>(ctx, kCount), Buffer<cl_float4>(ctx, kCount),
                            Buffer<float>(ctx, in), Buffer<float>(ctx, 6 * size_t(kCount)),
                            Buffer<float>(ctx, 6 * size_t(kCount))};
  }();
  return *b;
}

Kernel probe_kernel(const char* name) {
  ProbeBuffers& b = probe_buffers();
  Kernel k = test::default_context().program("tests/vectorization_probe.cl")->kernel(name);
  const std::string form = name;
  if (form == "bounce_aos")
    k.args(kCount, kSeed, b.normal, b.throughput, b.dir, b.throughput_out);
  else
    k.args(kCount, kSeed, b.in, form == "bounce_lanes" ? b.out_lanes : b.out);
  return k;
}

// Work items of a form: bounce_lanes takes eight items each.
size_t work_items(const char* name) { return std::string(name) == "bounce_lanes" ? kCount / 8 : kCount; }

// Largest difference between the outputs of the float3 form and the other two (all three run
// once first).
float forms_difference() {
  ProbeBuffers& b = probe_buffers();
  for (const char* name : {"bounce_aos", "bounce_soa", "bounce_lanes"}) probe_kernel(name).run(work_items(name));
  std::vector<cl_float4> dir = b.dir.read(), thr = b.throughput_out.read();
  float worst = 0.0f;
  for (const Buffer<float>* form : {&b.out, &b.out_lanes}) {
    std::vector<float> out = form->read();
    for (unsigned i = 0; i < kCount; ++i)
      for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::fabs(dir[i].s[c] - out[c * size_t(kCount) + i]));
        worst = std::max(worst, std::fabs(thr[i].s[c] - out[(3 + c) * size_t(kCount) + i]));
      }
  }
  return worst;
}

void BM_BounceForm(benchmark::State& state, const char* name) {
  static const float d = forms_difference();  // once for the three benchmarks
  if (!(d <= 1e-4f)) {
    state.SkipWithError(("the forms differ by " + std::to_string(d)).c_str());
    return;
  }
  Kernel k = probe_kernel(name);
  for (auto _ : state) k.run(work_items(name));
  state.SetItemsProcessed(int64_t(state.iterations()) * kCount);
  state.SetLabel(test::default_context().device().name);
}
BENCHMARK_CAPTURE(BM_BounceForm, aos_float3, "bounce_aos")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_BounceForm, soa_scalar, "bounce_soa")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_BounceForm, lanes_float8, "bounce_lanes")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace gdr
