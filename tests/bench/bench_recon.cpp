// Poisson reconstruction on a 1280x720 RGB frame of synthetic noisy data (default device): time
// per CG iteration and its memory bandwidth next to a plain copy kernel, and full L2 / L1 solves
// with the baseline CG (published iteration counts) and the fast solver (direct DCT solve for L2,
// multigrid-preconditioned CG for L1).
#include <benchmark/benchmark.h>

#include "recon/cg_solver.h"
#include "recon/dct_solver.h"
#include "recon/fast_solver.h"
#include "recon/reconstruct.h"
#include "recon/recon_fixtures.h"
#include "support/devices.h"

namespace gdr {
namespace {

constexpr int kW = 1280, kH = 720;

// Known image; primal noise sigma 0.2 (seed 1), gradient noise sigma 0.02 (seeds 2, 3).
const test::GradientImage& frame() {
  static test::GradientImage g = [] {
    test::GradientImage f = test::exact_problem(kW, kH);
    test::add_gaussian_noise(f.primal, 0.2f, 1);
    test::add_gaussian_noise(f.dx, 0.02f, 2);
    test::add_gaussian_noise(f.dy, 0.02f, 3);
    return f;
  }();
  return g;
}

// The benchmark frame's L2 system (alpha 0.2), ready to solve.
ReconSystem l2_problem(Context& ctx) {
  const auto& g = frame();
  ReconSystem problem(ctx, kW, kH, g.primal, g.dx, g.dy);
  problem.set_l2_weights(0.2f);
  problem.build_rhs();
  return problem;
}

// Device bytes one baseline CG iteration moves per pixel, in images of 3 floats (12 B): apply
// reads x and three weights and writes Ap (5), dot(p, Ap) reads 2, the x/r update reads 4 and
// writes 2 (6), dot(r, r) reads 1, the p update reads 2 and writes 1 (3).
constexpr double kCgBytesPerPixel = 12.0 * (5 + 2 + 6 + 1 + 3);

void BM_ReconCgIteration(benchmark::State& state) {
  Context& ctx = test::default_context();
  ReconSystem problem = l2_problem(ctx);
  CgSolver cg(ctx, kW, kH);
  const int iters = 10;
  for (auto _ : state) cg.solve(problem.system(), iters, 0.0);
  double n = double(state.iterations()) * iters;
  state.SetItemsProcessed(int64_t(n * kW * kH));
  state.SetBytesProcessed(int64_t(n * kW * kH * kCgBytesPerPixel));
  state.counters["cg_iters"] = benchmark::Counter(n, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel("per item: one pixel, one CG iteration; counter cg_iters: seconds per iteration");
}
BENCHMARK(BM_ReconCgIteration)->Unit(benchmark::kMillisecond)->UseRealTime();

// One multigrid-preconditioned CG iteration (with its V-cycle).
void BM_ReconFastIteration(benchmark::State& state) {
  Context& ctx = test::default_context();
  ReconSystem problem = l2_problem(ctx);
  FastSolver fast(ctx, kW, kH);
  const int iters = 5;
  for (auto _ : state) fast.solve(problem.system(), iters, 0.0);
  double n = double(state.iterations()) * iters;
  state.SetItemsProcessed(int64_t(n * kW * kH));
  state.counters["pcg_iters"] = benchmark::Counter(n, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ReconFastIteration)->Unit(benchmark::kMillisecond)->UseRealTime();

// The direct L2 solve alone (DCT along y, tridiagonal along x, inverse DCT).
void BM_ReconDctSolve(benchmark::State& state) {
  Context& ctx = test::default_context();
  ReconSystem problem = l2_problem(ctx);
  DctSolver dct(ctx, kW, kH);
  for (auto _ : state) dct.solve(problem.system(), 0.2f);
  state.SetItemsProcessed(int64_t(state.iterations()) * kW * kH);
}
BENCHMARK(BM_ReconDctSolve)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same CG iterations with deferred kernel timing (launches queued without a wait each).
void BM_ReconCgIterationDeferred(benchmark::State& state) {
  Context& ctx = test::default_context();
  ReconSystem problem = l2_problem(ctx);
  CgSolver cg(ctx, kW, kH);
  const int iters = 10;
  DeferredTiming deferred(ctx);
  for (auto _ : state) cg.solve(problem.system(), iters, 0.0);
  state.counters["cg_iters"] = benchmark::Counter(double(state.iterations()) * iters,
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ReconCgIterationDeferred)->Unit(benchmark::kMillisecond)->UseRealTime();

// The bandwidth reference: copy one RGB float image (12 B read + 12 B written per pixel), as
// float4 words.
void BM_ReconCopyBandwidth(benchmark::State& state) {
  Context& ctx = test::default_context();
  Kernel k = ctx.program("util/copy.cl")->kernel("copy_float4");
  const int n = kW * kH * 3 / 4;
  Buffer<cl_float4> in(ctx, size_t(n)), out(ctx, size_t(n));
  in.fill(cl_float4{{1, 2, 3, 0}});
  k.args(in, out, n);
  // Launches queued back to back (deferred timing), as the solvers run theirs.
  const int copies = 20;
  DeferredTiming deferred(ctx);
  for (auto _ : state) {
    for (int i = 0; i < copies; ++i) k.run(size_t(n));
    ctx.finish();
  }
  state.SetBytesProcessed(int64_t(state.iterations()) * copies * kW * kH * 24);
}
BENCHMARK(BM_ReconCopyBandwidth)->Unit(benchmark::kMillisecond)->UseRealTime();

// Full solves with the default settings; counters give what each reached.
void solve_bench(benchmark::State& state, ReconNorm norm, ReconSettings::Solver solver) {
  Context& ctx = test::default_context();
  const auto& g = frame();
  ReconSettings s;
  s.norm = norm;
  s.solver = solver;
  // A first call outside the timing: programs and the kept workspace (allocated and first
  // touched) are then ready, as in every call but the first of a render session.
  ReconResult r = reconstruct(ctx, kW, kH, g.primal, g.dx, g.dy, s, nullptr);
  for (auto _ : state) r = reconstruct(ctx, kW, kH, g.primal, g.dx, g.dy, s, nullptr);
  state.counters["residual"] = r.residual;
  state.counters["energy"] = r.energy;
  state.counters["iterations"] = r.iterations;
  state.counters["rmse_x1e4"] = 1e4 * test::rmse(r.rgb, g.truth);
  state.SetItemsProcessed(int64_t(state.iterations()) * kW * kH);
}
void BM_ReconL2Cg(benchmark::State& s) { solve_bench(s, ReconNorm::L2, ReconSettings::Solver::CG); }
void BM_ReconL2Fast(benchmark::State& s) { solve_bench(s, ReconNorm::L2, ReconSettings::Solver::Fast); }
void BM_ReconL1Cg(benchmark::State& s) { solve_bench(s, ReconNorm::L1, ReconSettings::Solver::CG); }
void BM_ReconL1Fast(benchmark::State& s) { solve_bench(s, ReconNorm::L1, ReconSettings::Solver::Fast); }
BENCHMARK(BM_ReconL2Cg)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
BENCHMARK(BM_ReconL2Fast)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);
BENCHMARK(BM_ReconL1Cg)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_ReconL1Fast)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

}  // namespace
}  // namespace gdr
