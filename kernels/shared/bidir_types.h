// State of the bidirectional integrator (`lt`, `bdpt`, `pm`, `vcm`), shared by its kernels and the
// host loop.
#pragma once
#include "shared/counters.h"

// The techniques one render combines (GdrBidirOptions.technique).
#define BIDIR_LT 0    // light subpaths to the camera, emission seen directly: nothing to weigh
#define BIDIR_BDPT 1  // every connection of a camera and a light subpath, weighted by MIS
#define BIDIR_PM 2    // progressive photon mapping: merging at the first rough camera vertex only
#define BIDIR_VCM 3   // bdpt's connections and merging at every rough camera vertex, weighted by MIS

#define BIDIR_MIS_BALANCE 1
#define BIDIR_MIS_POWER 2

// Per-render options of the kernels (the merging ones set per chunk: the radius shrinks by pass).
typedef struct GdrBidirOptions {
  int technique;   // BIDIR_*
  int mis;         // BIDIR_MIS_* (bdpt, vcm)
  int strategy_s;  // >= 0: only the strategy with s light and t camera vertices, unweighted
  int strategy_t;
  float radius;            // merging radius of this pass
  float vm_normalization;  // 1 / (pi r^2 N): N light subpaths merged with
  float vm_factor;         // MIS weight factor of merging against connections (0 without merging)
  float vc_factor;         // of connections against merging (0 without connections)
  int multiplex;           // 1: each path picks its length and one strategy from its numbers (bidir/strategies.h)
  int power_sums;          // 1: light subpaths also carry bdpt's sums under the power heuristic (G-BDPT's primal)
} GdrBidirOptions;

// bdpt_connect's vertex index that stands for the path's own (multiplexed) strategy's vertex.
#define BIDIR_OWN_STRATEGY 0xFFFFFFFFu

#define BIDIR_PATH_INFINITE 2  // a light subpath from a light at infinity (its first segment has no length)
#define BIDIR_PATH_ALL_SPECULAR 4  // a camera subpath with delta scatterings only so far (pm's emission)
#define BIDIR_PATH_POWER_SUMS 8  // the subpath carries power_dvcm and power_dvc (GdrBidirOptions.power_sums)

// A camera or light subpath between bounces. dvcm and dvc are the running MIS sums of SmallVCM
// (Georgiev et al. 2012, "Implementing Vertex Connection and Merging"): with them a vertex knows
// the weights of every strategy that could have sampled its subpath without walking it again.
// power_dvcm and power_dvc are bdpt's sums again under the power heuristic, where a primal is
// weighed by it apart from the sums of the options' heuristic (G-BDPT's; 0 elsewhere).
typedef struct GdrBidirPathState {
  float throughput[3];
  float rr_scale;        // largest component of the first throughput (Russian roulette's unit)
  float dvcm, dvc, dvm;
  float power_dvcm, power_dvc;
  unsigned int index;    // camera: the pixel; light: the subpath's index in its pass
  unsigned int sample;   // the pass
  int depth;             // scattering vertices so far (0: leaving the light or the camera)
  int stored;            // light subpaths: vertices written to the light-vertex store
  int flags;             // BIDIR_PATH_*
  int shown_s, shown_t;  // the one strategy this path adds (s light, t camera vertices), or -1: all
} GdrBidirPathState;

// A subpath vertex on a non-delta surface, kept for connections: the surface is found again from
// its triangle and barycentrics; wo points toward the vertex before it on its own subpath.
typedef struct GdrBidirVertex {
  unsigned int prim;
  float u, v;
  float wo[3];
  float throughput[3];
  float dvcm, dvc, dvm;
  float power_dvcm, power_dvc;  // GdrBidirPathState's
  int depth;  // scattering vertices up to and including this one
} GdrBidirVertex;

// Where a light subpath left its light (bidir_emit): what a shift that moves the subpath's first
// vertex evaluates the emission toward again (G-PM's photon shift, gbidir/photon_shift.h).
typedef struct GdrLightOrigin {
  float p[3];
  float n[3];  // area lights: the geometric normal there; 0 for the others
  int light;   // -1: the subpath left no light
  int pad0;
} GdrLightOrigin;

// Counters the kernels increment (atomic_inc), read after each step.
#define BIDIR_COUNTERS(X)                                                                               \
  X(BIDIR_COUNTER_NEXT_RAYS, "")                            /* rays written for the next bounce */      \
  X(BIDIR_COUNTER_SHADOW_RAYS, "")                          /* shadow rays written by this step */      \
  X(BIDIR_COUNTER_CONNECTABLE, "")                          /* camera vertices open to connections */   \
  X(BIDIR_COUNTER_CAMERA_CONNECTIONS, "bidir/camera_connections") /* light vertices sent to the camera */ \
  X(BIDIR_COUNTER_SUBPATHS, "bidir/light_subpaths")         /* light subpaths leaving a light */        \
  X(BIDIR_COUNTER_LIGHT_VERTICES, "bidir/light_vertices")   /* vertices kept for connections */         \
  X(BIDIR_COUNTER_CONNECTIONS, "bidir/connections")         /* camera-light vertex connections tried */ \
  X(BIDIR_COUNTER_NEE, "bidir/light_connections")           /* camera vertices connected to a light */  \
  X(BIDIR_COUNTER_MERGES, "bidir/merges")                   /* light vertices merged with */            \
  X(BIDIR_COUNTER_NONFINITE, "samples/nonfinite_rejected")  /* NaN or Inf contributions dropped */
enum { BIDIR_COUNTERS(GDR_COUNTER_ENUM) BIDIR_COUNTER_COUNT };
