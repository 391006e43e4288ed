// State of the wavefront path tracer, shared by its kernels and the host loop.
#pragma once
#include "shared/counters.h"

#define PATH_FLAG_SPECULAR 1  // the last bounce sampled a delta lobe (no MIS for emission hit)

typedef struct GdrPathState {
  float throughput[3];
  float bsdf_pdf;      // solid-angle pdf of the last BSDF sample (for MIS of emission hits)
  unsigned int pixel;  // y * width + x
  unsigned int sample; // sample index of this pixel
  int depth;           // number of bounces so far (0 at the camera vertex)
  int flags;           // PATH_FLAG_*
} GdrPathState;

// Per-launch parameters of the path-based kernels (pt, and gpt inside GdrGptParams).
typedef struct GdrPtParams {
  unsigned int seed;
  unsigned int first_pixel;  // the queue's slot (gpt: group) i traces pixel first_pixel + i
  unsigned int pixel_count;  // slots in this chunk
  unsigned int sample;       // sample index of the pass
  int max_depth;             // longest path in segments (camera vertex excluded); < 0: unbounded
  int rr_depth;              // bounces before Russian roulette starts
  int light_count;
  int env_light;             // index of the environment light, or -1
  int strategy;              // PT_STRATEGY_*
  int width;                 // film size
  int height;
} GdrPtParams;

#define PT_STRATEGY_MIS 0    // BSDF and light sampling combined by the power heuristic
#define PT_STRATEGY_BSDF 1   // BSDF sampling only
#define PT_STRATEGY_LIGHT 2  // light sampling only (emission seen through delta bounces kept)

// Counters the kernels increment (atomic_inc), read after each step.
#define PT_COUNTERS(X)                                                                    \
  X(PT_COUNTER_NEXT_RAYS, "")                       /* rays written for the next bounce */ \
  X(PT_COUNTER_SHADOW_RAYS, "")                     /* shadow rays written */              \
  X(PT_COUNTER_NONFINITE, "samples/nonfinite_rejected") /* NaN or Inf contributions dropped */
enum { PT_COUNTERS(GDR_COUNTER_ENUM) PT_COUNTER_COUNT };

// The counters of the emission seen by camera rays alone (path/seen_emission.h).
#define SEEN_COUNTERS(X)                                                              \
  X(SEEN_COUNTER_NONFINITE, "samples/nonfinite_rejected") /* NaN or Inf dropped */ \
  X(SEEN_COUNTER_LISTED, "")                              /* pixels listed for extra samples */
enum { SEEN_COUNTERS(GDR_COUNTER_ENUM) SEEN_COUNTER_COUNT };
