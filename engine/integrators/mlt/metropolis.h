// Metropolis light transport (`mlt`): primary-sample-space MLT (Kelemen et al. 2002) over the
// bidirectional kernels, with multiplexed strategies (Hachisuka et al. 2014; pbrt-v4's
// MLTIntegrator). A chain's state is the vector of uniforms a bidirectional path draws
// (kernels/sampling/path_sampler.h reads it through the sampler seam): its film position, its
// length, the one strategy (s, t) it is sampled by, and the numbers of its camera and light
// subpaths. The target f is the luminance of that strategy's MIS-weighted contribution over its
// selection probability.
//
// A render: the bootstrap draws `bootstrap` independent states (large steps), whose mean f is the
// normalization b (the image's integral over primary sample space) and from which the chains'
// starts are picked in proportion to f; then every step proposes a mutation of every chain (small
// or large), traces the proposals as one wavefront batch, accepts or rejects them, and splats
// both the current and the proposed contributions with their expected-value weights, times b.
// The image is the splats over the chains' steps. A pass is as many steps as make about one
// mutation a pixel, so --spp (or mutations_per_pixel) counts mutations a pixel.
//
// Under MPI every rank runs chains of its own (their numbers keyed by its rank) with its own
// bootstrap, over its share of the passes; the films are summed and divided by the job's steps.
//
// Parameters (IntegratorParams):
//   chains               Markov chains run side by side, one work item each (default 8192)
//   bootstrap            bootstrap samples (default 131072, at least one a chain)
//   sigma                small step: standard deviation of each dimension's perturbation (0.01)
//   large_step           probability of a large step, a fresh uniform state (0.3)
//   mutations_per_pixel  the render's length (default: --spp; --time may stop it earlier)
//   mis                  power (default) | balance: the strategies' weights
#pragma once
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "integrators/bidir/subpaths.h"
#include "integrators/mlt/markov_chains.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/splat_film.h"

namespace gdr {

struct MetropolisSettings {
  MltSettings mutation;
  int mis = BIDIR_MIS_POWER;
  size_t chains = 8192;
  size_t bootstrap = size_t(1) << 17;
  std::optional<int> mutations_per_pixel;
};
extern const std::vector<std::string> kMltParams;
MetropolisSettings mlt_settings(const IntegratorParams& params);

class Metropolis : public Integrator {
 public:
  Metropolis(const RenderInputs& inputs, const MetropolisSettings& settings);

  RenderResult render(const RenderSettings& settings) override;

  // The last render's normalization b: the integral of the target over primary sample space, the
  // image's luminance summed over its pixels (on rank 0 under MPI).
  double normalization() const { return normalization_; }

 private:
  static constexpr const char* kProgram = "mlt/mlt.cl";
  // Traces the paths of `states` (iteration p.sample) and writes each chain's contribution and f.
  void evaluate(const GdrPtParams& p, const Buffer<float>& states, Buffer<GdrSplat>& contributions,
                Buffer<float>& f);
  // The bootstrap: the sum of f over its samples and their count; each chain's start, then the
  // chains' current contributions.
  MarkovChains::Sample bootstrap(const GdrPtParams& base, uint32_t chain_seed);
  size_t bootstrap_rounds() const { return std::max<size_t>(1, (settings_.bootstrap + settings_.chains - 1) / settings_.chains); }

  RenderInputs in_;
  MetropolisSettings settings_;
  BidirSubpaths subpaths_;
  Kernel contribution_, splat_;
  GdrBidirOptions options_{};
  GdrPrimaryLayout layout_{};
  bool light_ = false;              // light subpaths can take part
  std::optional<MarkovChains> chains_;
  Buffer<Vec4> values_;             // camera subpaths' contributions, a chain each
  SplatFilm found_;                 // t = 1 contributions, a slot a chain (never gathered)
  Buffer<GdrSplat> current_, proposed_;  // contributions: film position, value over f
  SplatFilm splats_;                // the steps' expected-value splats
  size_t steps_per_gather_;
  Film film_;
  double normalization_ = 0;
};

}  // namespace gdr
