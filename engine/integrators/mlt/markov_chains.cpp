#include "integrators/mlt/markov_chains.h"

#include "util/error.h"

namespace gdr {

static_assert(sizeof(GdrMltParams) == 32, "GdrMltParams layout changed");

MarkovChains::MarkovChains(Context& context, const KernelFactory& kernels, const std::string& program,
                           size_t chains, size_t dims, const MltSettings& settings)
    : chains_(chains),
      dims_(dims),
      settings_(settings),
      propose_(kernels.make(program, "mlt_propose")),
      accept_(kernels.make(program, "mlt_accept")),
      current_(context, chains * dims),
      proposed_(context, chains * dims),
      f_current_(context, chains),
      f_proposed_(context, chains),
      weights_(context, chains),
      counters_(context, GDR_COUNTER_NAMES(MLT_COUNTERS)) {
  if (chains == 0 || dims == 0) throw Error("Markov chains: need at least one chain of one dimension");
  if (!(settings.sigma > 0.0f) || !(settings.large_step >= 0.0f && settings.large_step <= 1.0f)) {
    throw Error("Markov chains: sigma must be positive and large_step in [0, 1]");
  }
  counters_.reset();
}

GdrMltParams MarkovChains::params(uint32_t seed, uint32_t iteration) const {
  GdrMltParams p{};
  p.chains = cl_uint(chains_);
  p.dims = cl_uint(dims_);
  p.seed = seed;
  p.iteration = iteration;
  p.sigma = settings_.sigma;
  p.large_step = settings_.large_step;
  return p;
}

void MarkovChains::propose(uint32_t seed, uint32_t iteration) {
  propose_.args(params(seed, iteration), current_, proposed_, counters_.buffer()).run(chains_);
}

void MarkovChains::accept(uint32_t seed, uint32_t iteration) {
  accept_.args(params(seed, iteration), current_, proposed_, f_current_, f_proposed_, weights_, counters_.buffer())
      .run(chains_);
}

std::vector<cl_uint> MarkovChains::counts() {
  std::vector<cl_uint> c = counters_.read();
  counters_.reset();
  return c;
}

void MarkovChains::report(Stats* stats) {
  counts();
  counters_.report(stats);
}

}  // namespace gdr
