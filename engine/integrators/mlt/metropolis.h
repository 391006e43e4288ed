// Metropolis light transport (`mlt`): primary-sample-space MLT (Kelemen et al. 2002) over the
// bidirectional kernels, with multiplexed strategies (Hachisuka et al. 2014; pbrt-v4's
// MLTIntegrator). A chain's state is the vector of uniforms a bidirectional path draws
// (kernels/sampling/path_sampler.h reads it through the sampler seam): its film position, its
// length, the one strategy (s, t) it is sampled by, and the numbers of its camera and light
// subpaths. The target f is the luminance of that strategy's MIS-weighted contribution over its
// selection probability, and its one contribution record is that contribution at its film
// position (where the light vertex projects for t = 1). The chains, the bootstrap and the steps
// are the Metropolis loop's (metropolis_loop.h): a pass is about one mutation a pixel, so --spp
// (or mutations_per_pixel) counts mutations a pixel. The normalization b, the integral of f, is
// the image's luminance summed over its pixels: it is estimated apart, as Mitsuba's PSSMLT does,
// from `bootstrap` full bidirectional samples (every strategy of every length, MIS-weighted, their
// film positions stratified by pixel: MetropolisLoop::run's normalization), whose luminance
// varies far less than a multiplexed path's f.
//
// Parameters (IntegratorParams):
//   chains               Markov chains run side by side, one work item each (default: one a
//                        pixel, at most 32768)
//   bootstrap            bootstrap samples (default: four a chain, at least 65536), and at least as
//                        many full bidirectional samples for b
//   sigma                small step: standard deviation of each dimension's perturbation (0.01)
//   large_step           probability of a large step, a fresh uniform state (0.3)
//   mutations_per_pixel  the render's length (default: --spp; --time may stop it earlier)
//   start_cap            k > 0: the chains' start weights capped at the bootstrap's k-th largest f
//                        (metropolis_loop.cpp: bootstrap; default 0, off)
//   mis                  power (default) | balance: the strategies' weights
#pragma once
#include <string>
#include <vector>

#include "integrators/bidir/subpaths.h"
#include "integrators/mlt/metropolis_loop.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/splat_film.h"

namespace gdr {

struct MltIntegratorSettings {
  MetropolisSettings loop;
  int mis = BIDIR_MIS_POWER;
};
extern const std::vector<std::string> kMltParams;
MltIntegratorSettings mlt_settings(const IntegratorParams& params);

class Metropolis : public Integrator {
 public:
  Metropolis(const RenderInputs& inputs, const MltIntegratorSettings& settings);

  RenderResult render(const RenderSettings& settings) override;

  // The last render's normalization b: the integral of the target over primary sample space, the
  // image's luminance summed over its pixels (on rank 0 under MPI).
  double normalization() const { return normalization_; }

 private:
  static constexpr const char* kProgram = "mlt/mlt.cl";

  RenderInputs in_;
  MltIntegratorSettings settings_;
  BidirSubpaths subpaths_;
  Kernel contribution_, image_sample_;
  GdrBidirOptions options_{};
  Buffer<Vec4> values_;  // camera subpaths' contributions, a chain each
  SplatFilm found_;      // t = 1 contributions, a slot a chain (never gathered)
  Buffer<Vec4> light_sums_;  // b's samples: a path's t = 1 contributions
  Film film_;
  MetropolisLoop loop_;
  double normalization_ = 0;
};

}  // namespace gdr
