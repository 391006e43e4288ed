// A batch of Markov chains in primary sample space (kernels/mlt/chains.h): the layer the
// Metropolis integrators run over the bidirectional sampler. Each step proposes a mutation of
// every chain on the device, lets the caller evaluate the target at the proposals (f_proposed),
// and accepts or rejects them on the device, leaving the expected-value weights for the splats.
#pragma once
#include <string>
#include <vector>

#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "shared/mlt_types.h"

namespace gdr {

// The mutations' settings, with Kelemen et al.'s and pbrt's defaults.
struct MltSettings {
  float sigma = 0.01f;      // small step: standard deviation of the Gaussian perturbation of each dimension
  float large_step = 0.3f;  // probability of a large step, a fresh uniform state
  // 0: the target reads every dimension; n: the states are bidirectional paths of 1 .. n
  // segments, and a step touches the dimensions of their lengths alone (GdrMltParams.lengths).
  unsigned lengths = 0;
  // The caller reports how many leading dimensions each state it evaluates read (current_read,
  // proposed_read); a small step moves those of the current state and draws the others fresh.
  bool reported = false;
};

class MarkovChains {
 public:
  // `kernels` builds `program`, which includes mlt/chains.h. `chains` chains of `dims` dimensions.
  MarkovChains(Context& context, const KernelFactory& kernels, const std::string& program, size_t chains,
               size_t dims, const MltSettings& settings);

  // The states (dimension d of chain c at d * chains + c) and their targets. A caller seeds
  // current() and f_current() (the bootstrap) before the first step.
  Buffer<float>& current() { return current_; }
  Buffer<float>& f_current() { return f_current_; }
  // The proposals of this step, and the targets the caller evaluates there.
  const Buffer<float>& proposed() const { return proposed_; }
  Buffer<float>& f_proposed() { return f_proposed_; }
  // With MltSettings::reported, the leading dimensions each current state and each proposal
  // read, as the caller reports them when it evaluates them (a chain each).
  Buffer<cl_uint>& current_read() { return held_; }
  Buffer<cl_uint>& proposed_read() { return read_; }
  // After accept(): per chain, (weight of the current state before the step, weight of the proposal).
  const Buffer<cl_float2>& weights() const { return weights_; }
  // The sum of f over the large steps' proposals so far, and their count: uniform samples of
  // primary sample space, so sum / count estimates the integral of f.
  struct Sample {
    double sum = 0, count = 0;
  };
  Sample large_step_targets() const;

  void propose(uint32_t seed, uint32_t iteration);
  void accept(uint32_t seed, uint32_t iteration);
  // A large step for every chain (a bootstrap's fresh states), without counting it as a step.
  void propose_fresh(uint32_t seed, uint32_t iteration);
  // Chain c's current state becomes the one propose_fresh(seed, picks[c].y) drew for chain
  // picks[c].x; the caller sets f_current.
  void start_at(uint32_t seed, const std::vector<cl_uint2>& picks);

  size_t chains() const { return chains_; }
  size_t dims() const { return dims_; }
  // Proposals and acceptances by mutation kind (MLT_COUNTER_*) since the last call: one read from
  // the device, added to the totals report() gives the stats.
  std::vector<cl_uint> counts();
  void report(Stats* stats);

  // The parameters of step `iteration` as the kernels get them: a kernel of the caller's that
  // includes mlt/chains.h derives each chain's step kind and acceptance from them (mlt_control).
  GdrMltParams step_params(uint32_t seed, uint32_t iteration) const {
    return params(seed, iteration, settings_.large_step);
  }

 private:
  GdrMltParams params(uint32_t seed, uint32_t iteration, float large_step) const;

  Context& ctx_;
  size_t chains_, dims_;
  MltSettings settings_;
  Kernel propose_, accept_, seed_;
  Buffer<float> current_, proposed_, f_current_, f_proposed_;
  Buffer<cl_float2> weights_, large_targets_;
  Buffer<cl_uint> held_, read_;
  DeviceCounters counters_;
  DeviceCounters uncounted_;  // propose_fresh's: not steps of the chains
};

}  // namespace gdr
