// What the Metropolis integrators (mlt, gmlt) share: chains in primary sample space
// (markov_chains.h) driven through a render. The integrator says how to evaluate a batch of
// states (trace their paths and turn what they found into R contribution records a chain: film
// position, value over the target f, and f); the loop does the rest:
//   bootstrap  `bootstrap` fresh states, whose mean f estimates b (the target's integral over
//              primary sample space); the chains start at bootstrap states drawn in proportion to
//              f, and their current records are evaluated there (its time counts against --time);
//   steps      per pass, the steps that make about one mutation a pixel: propose, evaluate,
//              accept, then splat every record of the current state with weight 1 - a and of the
//              proposal with weight a (kernels/mlt/splats.h) into record r's film layer;
//   b          the target's integral, from every uniform sample of all ranks: the bootstrap's and
//              the large steps'; or, where the integrator gives a function whose integral is b,
//              the mean of that function over at least `bootstrap` fresh states stratified by
//              pixel (mlt: the image's luminance from full bidirectional samples; for gmlt's
//              target that cost more time than it saved error). Its time counts against --time.
// The film layers then hold sums whose image is b / (steps x chains) times them (Result::scale).
// Under MPI every rank runs chains (and samples) of its own, their numbers keyed by its rank.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "integrators/mlt/markov_chains.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/splat_film.h"

namespace gdr {

// The settings every Metropolis integrator reads: the mutations (sigma, large_step), chains,
// bootstrap and mutations_per_pixel.
struct MetropolisSettings {
  MltSettings mutation;
  size_t chains = 0;  // 0: one a pixel, at most kDefaultChains (resolve with for_film)
  size_t bootstrap = 0;  // 0: four a chain, at least 65536 (resolve with for_film)
  std::optional<int> mutations_per_pixel;
  size_t start_cap = 0;  // > 0: the chains' start weights capped at the bootstrap's k-th largest f
};
// Their names (a function: other integrators' parameter lists are built from it at start-up).
std::vector<std::string> metropolis_params();
// The default chain count's cap: enough work items to fill a GPU, about 1 GiB of path state.
constexpr size_t kDefaultChains = size_t(1) << 15;
// `s` with its chain and bootstrap counts resolved for the scene's film.
MetropolisSettings for_film(MetropolisSettings s, const Scene& scene);
MetropolisSettings metropolis_settings(const IntegratorParams& params);

class MetropolisLoop {
 public:
  // Traces the paths of `states` at `iteration` (the key of their numbers not in the states) and
  // writes each chain's records (record r of chain c at r * chains + c) and f, and with
  // MltSettings::reported the leading dimensions each state read into `read`.
  using Evaluate = std::function<void(uint32_t iteration, const Buffer<float>& states, Buffer<GdrSplat>& records,
                                      Buffer<float>& f, Buffer<cl_uint>& read)>;
  // Writes into `f` a value at each of `states` (keyed by `iteration` as above).
  using Sample = std::function<void(uint32_t iteration, const Buffer<float>& states, Buffer<float>& f)>;

  // `program` holds the loop's kernels (mlt/chains.h, mlt/splats.h, mlt/uniform_states.h,
  // path/splat.h); record r splats into layers[r] (a film layer of the camera's size).
  MetropolisLoop(const RenderInputs& inputs, const KernelFactory& kernels, const std::string& program,
                 const MetropolisSettings& settings, std::vector<Buffer<Vec4>*> layers);

  struct Result {
    int passes = 0;            // of all ranks
    double normalization = 0;  // b
    double scale = 0;          // what turns the layers' sums into the image: b / (steps x chains)
  };
  // The chains hold states in `layout` (`mutation.lengths` and `reported` as MltSettings say);
  // nothing runs unless `contributes` (the layers stay black). `normalization`: a function whose
  // integral is b (else b is the target's integral from the chains' uniform samples).
  Result run(const RenderSettings& settings, const GdrPrimaryLayout& layout, const MltSettings& mutation,
             bool contributes, const Evaluate& evaluate, const Sample& normalization = nullptr);

  size_t chains() const { return settings_.chains; }

 private:
  MarkovChains::Sample bootstrap(uint32_t seed, const Evaluate& evaluate);
  // The integral of what `sample` returns over primary sample space in `layout`: the mean over at
  // least `bootstrap` fresh states, in whole sweeps over the film with one film position a pixel
  // (stratified, kernels/mlt/uniform_states.h), so that the estimate carries no variation across
  // the film, only that within each pixel. The sum and count of every rank's samples (a
  // collective under MPI).
  MarkovChains::Sample stratified_integral(const GdrPrimaryLayout& layout, uint32_t seed, const Sample& sample);
  size_t bootstrap_rounds() const;
  void splat(uint32_t seed, uint32_t step, size_t pending);
  void gather(size_t pending);

  RenderInputs in_;
  const KernelFactory& kernels_;
  std::string program_;
  MetropolisSettings settings_;
  std::vector<Buffer<Vec4>*> layers_;
  Kernel splat_, uniform_states_;
  std::optional<MarkovChains> chains_;
  Buffer<GdrSplat> current_, proposed_;  // R records a chain
  std::vector<SplatFilm> splats_;        // record r's splats
  Buffer<float> sample_states_, sample_f_;  // stratified_integral's
  size_t steps_per_gather_;
};

}  // namespace gdr
