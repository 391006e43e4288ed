#include "recon/reconstruct.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <climits>
#include <string>

#include "recon/cg_solver.h"
#include "recon/dct_solver.h"
#include "recon/fast_solver.h"
#include "recon/planes.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {
namespace {

// With tolerance 0 the fast solver stops at these instead of running to the cap. L2: relative to
// |b|, below the residual 50 CG iterations reach on the benchmark frame. L1: inexact rounds, each
// warm-started round stopping once its residual fell by kFastL1RoundTolerance or after
// kFastL1RoundIterations PCG iterations. Solving the rounds further reaches a higher L1 objective,
// not a lower one (the weights of nearly satisfied terms grow towards 1/reg and lock them in);
// these values reach a lower objective than the published 20 x 50 CG on the benchmark frame and on
// G-PT renders of the Cornell box, its caustics variant and the glossy plates.
constexpr double kFastL2Tolerance = 1e-4;
constexpr double kFastL1RoundTolerance = 0.15;
constexpr int kFastL1RoundIterations = 3;
// Below this alpha the k = 0 system of the direct solve is too close to singular in float.
constexpr float kDctMinAlpha = 1e-3f;

void check_input(int width, int height, const std::vector<float>& v, const char* what) {
  size_t expected = size_t(width) * size_t(height) * 3;
  if (v.size() != expected) {
    throw Error(std::string("reconstruct: ") + what + " has " + std::to_string(v.size()) +
                " values, expected " + std::to_string(expected) + " (" + std::to_string(width) +
                "x" + std::to_string(height) + " RGB)");
  }
}

// Runs whichever solver the settings ask for on the current weights of `problem`.
class Solver {
 public:
  Solver(Context& ctx, const ReconSettings& s, int w, int h) : fast_(s.solver == ReconSettings::Solver::Fast) {
    if (fast_) {
      fast_solver_ = std::make_unique<FastSolver>(ctx, w, h);
    } else {
      cg_ = std::make_unique<CgSolver>(ctx, w, h);
    }
  }
  // Solves the system of `problem` as its weights and b (and with residual_ready, r) stand.
  SolveOutcome solve(ReconSystem& problem, int max_iterations, double tolerance,
                     bool relative_to_start = false, bool residual_ready = false) {
    LinearSystem sys = problem.system();
    if (!fast_) return cg_->solve(sys, max_iterations, tolerance, relative_to_start, residual_ready);
    fast_solver_->weights_changed();
    return fast_solver_->solve(sys, max_iterations, tolerance, relative_to_start, residual_ready);
  }

 private:
  bool fast_;
  std::unique_ptr<FastSolver> fast_solver_;
  std::unique_ptr<CgSolver> cg_;
};

// The device buffers of one reconstruction, kept with the context for the next call of the same
// size and solver (one at a time: a different call replaces it).
struct Workspace {
  Workspace(Context& ctx, const ReconSettings& s, int w, int h)
      : width(w), height(h), solver_kind(s.solver), problem(ctx, w, h), solver(ctx, s, w, h) {}
  int width, height;
  ReconSettings::Solver solver_kind;
  ReconSystem problem;
  Solver solver;
  std::unique_ptr<DctSolver> dct;  // made on first use
};

Workspace& workspace(Context& ctx, const ReconSettings& s, int w, int h) {
  std::shared_ptr<void>& slot = ctx.kept("recon/workspace");
  auto* ws = static_cast<Workspace*>(slot.get());
  if (!ws || ws->width != w || ws->height != h || ws->solver_kind != s.solver) {
    slot.reset();  // release the old buffers before allocating new ones
    auto made = std::make_shared<Workspace>(ctx, s, w, h);
    ws = made.get();
    slot = std::move(made);
  }
  return *ws;
}

}  // namespace

const char* recon_norm_name(ReconNorm norm) {
  switch (norm) {
    case ReconNorm::L1: return "L1";
    case ReconNorm::L2: return "L2";
    case ReconNorm::Weighted: return "weighted";
  }
  return "?";
}

ReconSettings recon_settings(const std::string& norm, float alpha, const std::string& solver) {
  ReconSettings s;
  if (norm == "l1") {
    s.norm = ReconNorm::L1;
  } else if (norm == "l2") {
    s.norm = ReconNorm::L2;
  } else if (norm == "weighted") {
    s.norm = ReconNorm::Weighted;
  } else {
    throw Error("unknown reconstruction '" + norm + "' (expected l1, l2 or weighted)");
  }
  if (solver == "fast" || solver == "cg") {
    s.solver = solver == "fast" ? ReconSettings::Solver::Fast : ReconSettings::Solver::CG;
  } else {
    throw Error("unknown reconstruction solver '" + solver + "' (expected fast or cg)");
  }
  if (!std::isfinite(alpha) || alpha < 0) {
    throw Error("reconstruction alpha must be a finite value >= 0, got " + std::to_string(alpha));
  }
  s.alpha = alpha;
  return s;
}

ReconResult reconstruct(Context& ctx, int width, int height, const std::vector<float>& primal_rgb,
                        const std::vector<float>& dx_rgb, const std::vector<float>& dy_rgb,
                        const ReconSettings& settings, Stats* stats, const ReconVariance* variance) {
  // Kernels index the planar buffers (recon/planes.h) with 32-bit ints.
  if (width <= 0 || height <= 0 || width > INT_MAX - GDR_RECON_ALIGN || height > INT_MAX / 4 ||
      double(gdr_recon_stride(width)) * gdr_recon_rows(height) > INT_MAX / 2) {
    throw Error("reconstruct: invalid image size " + std::to_string(width) + "x" + std::to_string(height));
  }
  check_input(width, height, primal_rgb, "primal");
  check_input(width, height, dx_rgb, "dx");
  check_input(width, height, dy_rgb, "dy");
  const bool l1 = settings.norm == ReconNorm::L1;
  const bool weighted = settings.norm == ReconNorm::Weighted;
  if (weighted) {
    if (!variance) throw Error("reconstruct: the weighted form needs variance estimates of primal, dx and dy");
    check_input(width, height, variance->primal, "primal variance");
    check_input(width, height, variance->dx, "dx variance");
    check_input(width, height, variance->dy, "dy variance");
    if (!(settings.variance_floor > 0) || !std::isfinite(settings.variance_floor)) {
      throw Error("reconstruct: the variance floor must be a finite value > 0");
    }
  }
  const bool fast = settings.solver == ReconSettings::Solver::Fast;
  auto start = std::chrono::steady_clock::now();
  // The solvers' launches are queued without waiting on each (the host reads a residual per
  // iteration anyway, which keeps it in step).
  DeferredTiming deferred(ctx);

  Workspace& ws = workspace(ctx, settings, width, height);
  ReconSystem& problem = ws.problem;
  Solver& solver = ws.solver;
  problem.load(primal_rgb, dx_rgb, dy_rgb);
  const int cap = std::max(0, settings.cg_iterations);
  double l2_tol = settings.tolerance > 0 ? settings.tolerance : fast ? kFastL2Tolerance : 0.0;
  double l1_tol = settings.tolerance > 0 ? settings.tolerance : fast ? kFastL1RoundTolerance : 0.0;

  ReconResult result;
  if (weighted) {
    // Per-pixel weights: no direct solve, the (P)CG from the primal.
    problem.set_variance_weights(*variance, settings.alpha, settings.variance_floor);
    problem.build_rhs();
    SolveOutcome o = solver.solve(problem, cap, l2_tol);
    result.iterations = o.iterations;
    result.residual = o.residual;
  } else if (!l1) {
    problem.set_l2_weights(settings.alpha);
    // With every term present the weights are uniform and a direct solve gives x; the PCG then
    // only checks its residual (and polishes it, should float rounding leave it above tolerance).
    problem.build_rhs();
    if (fast && problem.nonfinite_inputs() == 0 && std::isfinite(settings.alpha) &&
        settings.alpha >= kDctMinAlpha && DctSolver::supports(height)) {
      if (!ws.dct) ws.dct = std::make_unique<DctSolver>(ctx, width, height);
      ws.dct->solve(problem.system(), settings.alpha);
    }
    SolveOutcome o = solver.solve(problem, cap, l2_tol);
    result.iterations = o.iterations;
    result.residual = o.residual;
  } else {
    // Reweighting starts from the primal, not from an L2 solution: L2 smears an outlier over its
    // neighbourhood, where smooth, nearly satisfied terms then get large weights and lock the
    // smear in as reg shrinks.
    // reg is published for images of order 1; brighter images scale it with their RMS so that
    // the weights (and the conditioning of each round) do not depend on the exposure.
    double scale = std::max(1.0, problem.primal_rms());
    if (!std::isfinite(scale)) scale = 1.0;
    float reg = float((settings.l1_reg > 0 ? settings.l1_reg : 0.05f) * scale);
    for (int round = 0; round < settings.l1_rounds; ++round, reg *= 0.5f) {
      // reg stays a normal float however many rounds are asked for.
      if (reg < 1e-30f) reg = 1e-30f;
      problem.set_l1_weights(settings.alpha, reg);
      SolveOutcome o = solver.solve(problem, fast ? std::min(cap, kFastL1RoundIterations) : cap,
                                    l1_tol, fast, true);
      result.iterations += o.iterations;
      result.residual = o.residual;
    }
  }
  result.energy = weighted ? problem.weighted_energy() : problem.energy(settings.alpha, !l1);
  unsigned nonfinite_outputs = 0;
  result.rgb = problem.result(&nonfinite_outputs);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (problem.nonfinite_inputs() > 0) {
    log::warn("reconstruct: ", problem.nonfinite_inputs(), " non-finite input values ignored");
  }
  if (stats) {
    stats->add_count("recon/nonfinite_inputs", problem.nonfinite_inputs());
    if (nonfinite_outputs) stats->add_count("recon/nonfinite_outputs", nonfinite_outputs);
    stats->add_count("recon/iterations", uint64_t(result.iterations));
    stats->set("recon/residual", result.residual);
    stats->set("recon/energy", result.energy);
    stats->set("recon/norm", recon_norm_name(settings.norm));
    stats->set("recon/solver", fast ? "fast" : "cg");
    stats->add_time("recon/solve", result.seconds);
  }
  return result;
}

}  // namespace gdr
