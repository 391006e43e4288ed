// Markov chains in primary sample space (Kelemen et al. 2002), shared by their kernels
// (kernels/mlt) and the host layer that drives them (engine/integrators/mlt/markov_chains). A
// chain's state is a vector of `dims` uniforms in [0, 1); a batch of chains is stored as
// structure of arrays: dimension d of chain c at d * chains + c.
#pragma once
#include "shared/counters.h"
#include "shared/sampler_types.h"

typedef struct GdrMltParams {
  unsigned int chains;     // chains in the batch
  unsigned int dims;       // primary-sample dimensions per chain
  unsigned int seed;
  unsigned int iteration;  // the step every chain takes now (keys its random numbers)
  float sigma;             // small step: standard deviation of the Gaussian perturbation
  float large_step;        // probability that a step is a large one: a fresh uniform state
  unsigned int lengths;    // 0: the target reads every dimension; n: the state is a bidirectional
                           // path's (shared/sampler_types.h), whose first dimension picks its
                           // length of 1 .. n segments and which reads the first
                           // 4 GDR_PRIMARY_BLOCKS(length) dimensions alone (mlt/chains.h)
  unsigned int reported;   // 1: the caller reports how many leading dimensions each evaluated
                           // state read (its target reads no others)
} GdrMltParams;

// Proposals and acceptances by mutation kind (atomic_inc).
#define MLT_COUNTERS(X)                                     \
  X(MLT_COUNTER_SMALL_STEPS, "mlt/small_steps")             \
  X(MLT_COUNTER_SMALL_ACCEPTED, "mlt/small_steps_accepted") \
  X(MLT_COUNTER_LARGE_STEPS, "mlt/large_steps")             \
  X(MLT_COUNTER_LARGE_ACCEPTED, "mlt/large_steps_accepted")
enum { MLT_COUNTERS(GDR_COUNTER_ENUM) MLT_COUNTER_COUNT };
