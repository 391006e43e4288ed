// State of the gradient-domain path tracer (G-PT), shared by its kernels and the host loop.
// Each pixel sample is a group: one base path and four offset paths through the neighbouring
// pixels (+x, -x, +y, -y), traced in the same wavefront.
#pragma once
#include "shared/gradient_types.h"
#include "shared/manifold_types.h"
#include "shared/pt_types.h"

#define GPT_SHIFT_HYBRID 0  // half-vector copy + reconnection
#define GPT_SHIFT_REPLAY 1  // random-number replay
#define GPT_SHIFT_MANIFOLD 2  // hybrid, and a manifold walk across specular chains between rough vertices

typedef struct GptBaseState {
  GdrPathState path;    // the state every path carries (kernels/path stages work on it)
  // The vertex x_k shaded in the last shade step, for the shift step that follows.
  unsigned int prim;
  float b1, b2;
  int sample_delta;     // the BSDF sample at x_k took a delta lobe
  float wi[3];          // sampled direction at x_k (world)
  int sample_transmitted;
  float wo[3];          // direction from x_k toward the previous vertex (world)
  float sample_eta;     // relative IOR across x_k (wi side / wo side)
  float rr_prob;        // Russian-roulette survival probability applied at x_k (1: none)
  GbdptSums mis;        // G-BDPT: the camera subpath's bidirectional MIS sums
} GptBaseState;

typedef struct GdrGptParams {
  GdrPtParams path;       // pixel_count counts groups; strategy is always MIS
  int shift;              // GPT_SHIFT_*
  float shift_threshold;  // roughness at or below which a vertex is glossy (not reconnectable)
  // G-VCM: merging's factors in the bidirectional sums (GdrBidirOptions' of the pass; 0 elsewhere).
  float vm_factor, vc_factor;
} GdrGptParams;

// Accumulators per group (float4 each): contributions of the base to the pair with neighbour k,
// contributions of offset k, the direct layer's paths other than the emission seen from the camera
// (G-BDPT's light-traced paths it cannot shift), G-BDPT's own primal under --primal power
// (GDR_GBDPT_POWER_PRIMAL: gbidir/weights.h; unused elsewhere, where the primal is the pairs'
// mean; without the seen emission), and the emission seen directly from the camera, the base's
// and that of the pass's extra camera samples (--direct-samples: integrators/gpt/direct_samples.h;
// w counts the samples that saw some). The direct layer and the seen emission stay out of the
// gradients.
#define GPT_ACC_BASE(k) (k)
#define GPT_ACC_OFFSET(k) (4 + (k))
#define GPT_ACC_DIRECT 8
#define GPT_ACC_PRIMAL 9
#define GPT_ACC_SEEN 10
#define GPT_ACC_COUNT 11

// Next-event contributions waiting for their shadow rays (float4 each, per group): the base's
// share for pair k and joined offset k's (both behind the base's shadow ray), traced offset k's
// (behind its own shadow ray), and the base's primal (GPT_ACC_PRIMAL's, behind the base's ray).
// A step writes the entries behind each ray it appends, and only those: gpt_shadow reads no other.
#define GPT_PEND_BASE(k) (k)
#define GPT_PEND_JOINED(k) (4 + (k))
#define GPT_PEND_OWN(k) (8 + (k))
#define GPT_PEND_PRIMAL 12
#define GPT_PEND_COUNT 13

// Shadow-ray ids: group * 8 + kind, kind 0 = the base's ray, 1 + k = offset k's own ray.
#define GPT_SHADOW_ID(group, kind) ((group) * 8u + (uint)(kind))

// Counters (atomic_inc), read after each step: queue sizes, then shifts by kind and failures by
// reason.
#define GPT_COUNTERS(X)                                                                              \
  X(GPT_COUNTER_BASE_RAYS, "")                                                                       \
  X(GPT_COUNTER_OFFSET_RAYS, "")                                                                     \
  X(GPT_COUNTER_SHADOW_RAYS, "")                                                                     \
  X(GPT_COUNTER_RECONNECT_RAYS, "")                                                                  \
  X(GPT_COUNTER_SHIFT_GROUPS, "")                           /* groups with an offset left to shift */ \
  X(GPT_COUNTER_MANIFOLD_WALKS, "")                                                                  \
  X(GPT_COUNTER_NONFINITE, "samples/nonfinite_rejected")                                             \
  X(GPT_COUNTER_SHIFT_RECONNECT, "shifts/reconnection")                                              \
  X(GPT_COUNTER_SHIFT_HALF_VECTOR, "shifts/half_vector")                                             \
  X(GPT_COUNTER_SHIFT_DELTA, "shifts/delta_lobe")                                                    \
  X(GPT_COUNTER_SHIFT_DIRECTION, "shifts/direction_copy")   /* toward the environment */             \
  X(GPT_COUNTER_SHIFT_REPLAY, "shifts/replay")                                                       \
  X(GPT_COUNTER_SHIFT_MANIFOLD, "shifts/manifold")                                                   \
  X(GPT_COUNTER_FAIL_OUTSIDE, "shift_failures/outside_image")                                        \
  X(GPT_COUNTER_FAIL_LOBE, "shift_failures/lobe_mismatch")  /* delta vs non-delta, or lobe missing */ \
  X(GPT_COUNTER_FAIL_REFRACTION, "shift_failures/refraction") /* total internal reflection in one */ \
  X(GPT_COUNTER_FAIL_OCCLUDED, "shift_failures/occluded")   /* reconnection segment blocked */       \
  X(GPT_COUNTER_FAIL_ENVIRONMENT, "shift_failures/environment_mismatch") /* one escaped */           \
  X(GPT_COUNTER_FAIL_NOT_INVERTIBLE, "shift_failures/not_invertible") /* the reverse shift differs */ \
  X(GPT_COUNTER_FAIL_ZERO, "shift_failures/zero_pdf_or_value") /* or inconsistent sides */           \
  X(GPT_COUNTER_FAIL_NONFINITE, "shift_failures/nonfinite") /* throughput or pdf ratio overflowed */ \
  X(GPT_COUNTER_FAIL_MANIFOLD, "shift_failures/manifold") /* the walk failed (manifold/fail_*) */       \
  X(GPT_COUNTER_FAIL_CHAIN_LONG, "manifold/fail_chain_too_long") /* over MANIFOLD_MAX_CHAIN vertices */ \
  X(GPT_COUNTER_CONNECTABLE, "")                            /* G-BDPT: rough camera vertices recorded */ \
  X(GPT_COUNTER_CONNECTIONS, "gbdpt/connections")           /* camera-light vertex connections tried */ \
  X(GPT_COUNTER_FAIL_GLOSSY_CONNECTION, "shift_failures/glossy_connection") /* no reconnection there */ \
  X(GPT_COUNTER_MERGES, "gpm/merges")                       /* G-PM: photons merged at base visible points */ \
  X(GPT_COUNTER_FAIL_PHOTON_PARENT, "shift_failures/photon_parent") /* a delta vertex before the photon */ \
  X(GPT_COUNTER_LT_OFFSET_RAYS, "")                         /* G-BDPT: light tracing's offset camera rays */ \
  X(GPT_COUNTER_LT_OFFSETS, "gbdpt/light_tracing_offsets")  /* light tracing's offsets formed and visible */ \
  X(GPT_COUNTER_FAIL_PHOTON_LOST, "shift_failures/photon_lost") /* offset photon outside the radius, or no photon */
enum { GPT_COUNTERS(GDR_COUNTER_ENUM) GPT_COUNTER_COUNT };

// The base's specular chain while offsets wait for it (GPT_MODE_MANIFOLD), per group: from its
// rough vertex x_b through the specular vertices the base has reached so far. When the base
// reaches the next rough vertex, each waiting offset gets a manifold walk from its own rough
// vertex to that one.
typedef struct GptChain {
  int open;   // offsets wait for this chain
  int count;  // specular vertices recorded; the last one's lobe is filled when the base leaves it
  GdrManifoldPoint origin;  // x_b
  float origin_pdf;         // the base's pdf of its direction leaving x_b
  float origin_rr;          // and its Russian-roulette survival probability there
  GdrManifoldVertex v[MANIFOLD_MAX_CHAIN];
  float pdf[MANIFOLD_MAX_CHAIN];  // the base's pdf of the direction leaving each vertex (delta: the lobe's probability)
  float rr[MANIFOLD_MAX_CHAIN];
} GptChain;
