// The reconstruction kernels come in two forms (kernels/recon/grid.h): 16-float chunks for CPU
// devices and one float per work item for GPUs. Both run here on the CPU device (the GPU form
// through GDR_RECON_VECTOR=1) and must give the same images, for every norm (the weighted form
// too) and solver, on sizes that are and are not multiples of the row alignment, with and without
// missing inputs.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "recon/planes.h"
#include "recon/reconstruct.h"
#include "recon_fixtures.h"
#include "support/devices.h"

namespace gdr {
namespace {

// A context whose reconstruction programs are built for `vec`-float chunks (the width is fixed
// with the context at its first use).
std::unique_ptr<Context> context_with_vector(const char* vec) {
  setenv("GDR_RECON_VECTOR", vec, 1);
  auto ctx = std::make_unique<Context>(select_device(""));
  EXPECT_EQ(recon_vector_width(*ctx), std::atoi(vec));
  unsetenv("GDR_RECON_VECTOR");
  return ctx;
}

TEST(ReconVectorForms, GpuFormMatchesCpuForm) {
  auto scalar = context_with_vector("1");
  auto wide = context_with_vector("16");
  EXPECT_EQ(recon_vector_width(*scalar), 1);  // kept, whatever the environment says now
  for (auto [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {7, 5}, {16, 9}, {37, 23}, {65, 18}}) {
    test::GradientImage g = test::exact_problem(w, h);
    test::add_gaussian_noise(g.primal, 0.2f, 5);  // seed 5
    test::add_gaussian_noise(g.dx, 0.05f, 6);     // seed 6
    test::add_gaussian_noise(g.dy, 0.05f, 7);     // seed 7
    g.primal[0] = NAN;
    for (const test::ReconCase& c : test::all_cases()) {
      SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " " + test::case_name(c));
      ReconSettings s = test::converged(c.norm, c.solver);
      // Late L1 rounds (reg below ~1e-5) amplify rounding differences between the forms' summation
      // orders until converged solves differ by ~1e-3 after 20 rounds (about 1e-6 after one), so
      // the forms are compared over the first ten.
      s.l1_rounds = 10;
      ReconResult a = reconstruct(*scalar, w, h, g.primal, g.dx, g.dy, s, nullptr);
      ReconResult b = reconstruct(*wide, w, h, g.primal, g.dx, g.dy, s, nullptr);
      // Converged solves of the same system; summation order differs between the forms.
      EXPECT_LT(test::max_abs_error(a.rgb, b.rgb), 1e-3);
      EXPECT_NEAR(a.energy, b.energy, 1e-4 * (1.0 + b.energy));
      // The same preconditioner, so about the same work.
      EXPECT_NEAR(a.iterations, b.iterations, 2 + 0.2 * b.iterations);
    }
    // The weighted form, with variance estimates spread over two decades (and some zeros).
    ReconVariance var{g.primal, g.dx, g.dy};
    for (auto* v : {&var.primal, &var.dx, &var.dy}) {
      for (size_t i = 0; i < v->size(); ++i) (*v)[i] = (i % 7 == 0) ? 0.0f : 1e-3f * float(1 + (i * 37) % 100);
    }
    for (auto solver : {ReconSettings::Solver::CG, ReconSettings::Solver::Fast}) {
      SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " weighted");
      ReconSettings s = test::converged(ReconNorm::Weighted, solver);
      ReconResult a = reconstruct(*scalar, w, h, g.primal, g.dx, g.dy, s, nullptr, &var);
      ReconResult b = reconstruct(*wide, w, h, g.primal, g.dx, g.dy, s, nullptr, &var);
      EXPECT_LT(test::max_abs_error(a.rgb, b.rgb), 1e-3);
      EXPECT_NEAR(a.energy, b.energy, 1e-4 * (1.0 + b.energy));
      EXPECT_NEAR(a.iterations, b.iterations, 2 + 0.2 * b.iterations);
    }
  }
}

TEST(ReconVectorForms, RejectsOtherWidths) {
  setenv("GDR_RECON_VECTOR", "8", 1);
  Context ctx(select_device(""));
  test::GradientImage g = test::exact_problem(4, 4);
  EXPECT_THROW(reconstruct(ctx, 4, 4, g.primal, g.dx, g.dy, ReconSettings{}, nullptr), Error);
  unsetenv("GDR_RECON_VECTOR");
}

}  // namespace
}  // namespace gdr
