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
  // After accept(): per chain, (weight of the current state before the step, weight of the proposal).
  const Buffer<cl_float2>& weights() const { return weights_; }

  void propose(uint32_t seed, uint32_t iteration);
  void accept(uint32_t seed, uint32_t iteration);

  size_t chains() const { return chains_; }
  size_t dims() const { return dims_; }
  // Proposals and acceptances by mutation kind (MLT_COUNTER_*) since the last call: one read from
  // the device, added to the totals report() gives the stats.
  std::vector<cl_uint> counts();
  void report(Stats* stats);

 private:
  GdrMltParams params(uint32_t seed, uint32_t iteration) const;

  size_t chains_, dims_;
  MltSettings settings_;
  Kernel propose_, accept_;
  Buffer<float> current_, proposed_, f_current_, f_proposed_;
  Buffer<cl_float2> weights_;
  DeviceCounters counters_;
};

}  // namespace gdr
