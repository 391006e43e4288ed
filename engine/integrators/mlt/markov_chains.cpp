#include "integrators/mlt/markov_chains.h"

#include "util/error.h"

namespace gdr {

static_assert(sizeof(GdrMltParams) == 32, "GdrMltParams layout changed");

MarkovChains::MarkovChains(Context& context, const KernelFactory& kernels, const std::string& program,
                           size_t chains, size_t dims, const MltSettings& settings)
    : ctx_(context),
      chains_(chains),
      dims_(dims),
      settings_(settings),
      propose_(kernels.make(program, "mlt_propose")),
      accept_(kernels.make(program, "mlt_accept")),
      seed_(kernels.make(program, "mlt_seed")),
      current_(context, chains * dims),
      proposed_(context, chains * dims),
      f_current_(context, chains),
      f_proposed_(context, chains),
      weights_(context, chains),
      large_targets_(context, chains),
      held_(context, settings.reported ? chains : 0),
      read_(context, settings.reported ? chains : 0),
      counters_(context, GDR_COUNTER_NAMES(MLT_COUNTERS)),
      uncounted_(context, GDR_COUNTER_NAMES(MLT_COUNTERS)) {
  if (chains == 0 || dims == 0) throw Error("Markov chains: need at least one chain of one dimension");
  if (!(settings.sigma > 0.0f) || !(settings.large_step >= 0.0f && settings.large_step <= 1.0f)) {
    throw Error("Markov chains: sigma must be positive and large_step in [0, 1]");
  }
  current_.fill(0.0f);  // a defined first state for propose_fresh to start from
  large_targets_.fill(cl_float2{});
  held_.fill(0u);
  counters_.reset();
}

GdrMltParams MarkovChains::params(uint32_t seed, uint32_t iteration, float large_step) const {
  GdrMltParams p{};
  p.chains = cl_uint(chains_);
  p.dims = cl_uint(dims_);
  p.seed = seed;
  p.iteration = iteration;
  p.sigma = settings_.sigma;
  p.large_step = large_step;
  p.lengths = settings_.lengths;
  p.reported = settings_.reported ? 1u : 0u;
  return p;
}

void MarkovChains::propose(uint32_t seed, uint32_t iteration) {
  propose_.args(params(seed, iteration, settings_.large_step), current_, proposed_, held_, counters_.buffer())
      .run(chains_);
}

void MarkovChains::propose_fresh(uint32_t seed, uint32_t iteration) {
  propose_.args(params(seed, iteration, 1.0f), current_, proposed_, held_, uncounted_.buffer()).run(chains_);
}

void MarkovChains::start_at(uint32_t seed, const std::vector<cl_uint2>& picks) {
  if (picks.size() != chains_) throw Error("Markov chains: one start a chain");
  Buffer<cl_uint2> from(ctx_, picks);
  seed_.args(params(seed, 0, settings_.large_step), from, current_).run(chains_);
}

void MarkovChains::accept(uint32_t seed, uint32_t iteration) {
  accept_
      .args(params(seed, iteration, settings_.large_step), current_, proposed_, f_current_, f_proposed_, weights_,
            large_targets_, held_, read_, counters_.buffer())
      .run(chains_);
}

MarkovChains::Sample MarkovChains::large_step_targets() const {
  Sample s;
  for (const cl_float2& t : large_targets_.read()) {
    s.sum += t.s[0];
    s.count += t.s[1];
  }
  return s;
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
