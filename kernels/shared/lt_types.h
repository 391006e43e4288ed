// State of the light tracer (`lt`), shared by its kernels and the host loop.
#pragma once
#include "shared/counters.h"

typedef struct GdrLightPathState {
  float throughput[3];
  float rr_scale;        // largest component of the first throughput (Russian roulette's unit)
  unsigned int index;    // the light subpath's index in its pass
  unsigned int sample;   // the pass
  int depth;             // scattering vertices so far (0: leaving the light)
  int pad0;
} GdrLightPathState;

// Counters the kernels increment (atomic_inc), read after each step.
#define LT_COUNTERS(X)                                                                         \
  X(LT_COUNTER_NEXT_RAYS, "")                            /* rays written for the next bounce */ \
  X(LT_COUNTER_SHADOW_RAYS, "lt/camera_connections")     /* vertices connected to the camera */ \
  X(LT_COUNTER_SUBPATHS, "lt/light_subpaths")            /* light subpaths leaving a light */   \
  X(LT_COUNTER_NONFINITE, "samples/nonfinite_rejected")  /* NaN or Inf contributions dropped */
enum { LT_COUNTERS(GDR_COUNTER_ENUM) LT_COUNTER_COUNT };
