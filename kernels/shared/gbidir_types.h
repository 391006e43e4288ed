// State of the gradient-domain bidirectional integrator (`gbdpt`), shared by its kernels and the
// host loop. Its camera subpaths are G-PT's groups (shared/gpt_types.h: a base and four offsets
// through the neighbouring pixels), its light subpaths the bidirectional integrator's
// (shared/bidir_types.h, one per group); these records join the two.
#pragma once
#include "shared/bidir_types.h"
#include "shared/gradient_types.h"

// How an offset stands at a camera vertex its base may connect from.
#define GBDPT_OFFSET_NONE 0    // dead, or waiting: contributes nothing, the base takes the full weight
#define GBDPT_OFFSET_OWN 1     // at a vertex of its own (its connections need rays of their own)
#define GBDPT_OFFSET_SHARED 2  // at the base's vertex (joined): shares the base's connection segments
#define GBDPT_OFFSET_GLOSSY 3  // at a vertex of its own, but the shift there is no reconnection: fails

// The layers G-BDPT's light tracing adds a pixel during a pass (gbidir/light_tracing.h): the
// accumulators' (GPT_ACC_BASE(k), GPT_ACC_OFFSET(k), GPT_ACC_DIRECT for the paths it cannot shift,
// and GPT_ACC_PRIMAL). A slot's first pair holds GBDPT_LT_UNSHIFTED as its R for those.
#define GBDPT_LT_LAYERS (GPT_ACC_PRIMAL + 1)
#define GBDPT_LT_UNSHIFTED (-1.0f)

// The photons a recorded vertex merges with that gpm_count lists for the later merge launches
// (gbidir/merge.h); a vertex with more walks the grid again. On the caustics box at 256 px a vertex
// merges with about two.
#define GPM_LISTED 8

// What a photon's parent is (the vertex its light subpath reached it from; gbidir/photon_shift.h).
#define GPM_PARENT_NONE 0      // a delta vertex: no reconnection
#define GPM_PARENT_SURFACE 1   // a rough vertex of the light subpath, stored just before the photon
#define GPM_PARENT_LIGHT 2     // the point the light subpath left its (area, point or spot) light from
#define GPM_PARENT_INFINITE 3  // a light at infinity (directional, constant, environment map)

// A rough camera vertex of a group, written by the shade step for the connections to the light
// subpath's stored vertices: the base's vertex and each offset's, with its throughput
// (f(y) |J| / p(x)), its pdf ratio to the base (p(y) |J| / p(x)) and its own MIS sums (the
// vertices' without light tracing's share, all_dvcm, all_dvc and all_dvm with it: index 0 the
// base's, 1 + k offset k's).
typedef struct GbdptCameraVertex {
  GdrBidirVertex base;
  GdrBidirVertex offset[GPT_OFFSETS];
  float all_dvcm[1 + GPT_OFFSETS], all_dvc[1 + GPT_OFFSETS], all_dvm[1 + GPT_OFFSETS];
  float ratio[GPT_OFFSETS];
  int state[GPT_OFFSETS];  // GBDPT_OFFSET_*
} GbdptCameraVertex;
