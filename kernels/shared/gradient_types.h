// Offset paths of the gradient-domain integrators, shared by their kernels and the host: each
// base path is paired with four offsets through the neighbouring pixels (+x, -x, +y, -y). The
// shift mappings (kernels/shift) and the gradient bookkeeping (kernels/gradient) work on these.
#pragma once

#define GPT_OFFSETS 4
#define GPT_DIR_PX 0
#define GPT_DIR_NX 1
#define GPT_DIR_PY 2
#define GPT_DIR_NY 3

// G-BDPT's and G-VCM's running MIS sums of a camera subpath (bidir/subpath_mis.h), twice: without
// light tracing's share (the strategies whose gradients are shifted, weighed among themselves),
// and with it (every strategy; gbidir/weights.h). dvm stays 0 where nothing merges. power_dvcm
// and power_dvc are bdpt's sums over every strategy under the power heuristic, for G-BDPT's
// primal under --primal power (0 elsewhere).
typedef struct GbdptSums {
  float dvcm, dvc, dvm;
  float all_dvcm, all_dvc, all_dvm;
  float power_dvcm, power_dvc;
} GbdptSums;

// What an offset path is doing.
#define GPT_MODE_DEAD 0          // the shift failed: contributes nothing, the base takes full weight
#define GPT_MODE_TRACE 1         // follows its own rays; its current vertex is its own hit
#define GPT_MODE_RECONNECTING 2  // reconnected to the base's next vertex; visibility pending
#define GPT_MODE_JOINED_RECENT 3 // joined the base at the base's current vertex
#define GPT_MODE_JOINED 4        // shares all the base's vertices from here on
#define GPT_MODE_MANIFOLD 5      // at a rough vertex, waits for the base's specular chain to end
                                 // at a rough vertex (GptChain); contributes nothing meanwhile

typedef struct GptOffsetState {
  float throughput[3];  // f(y) |J| / p(x) of the prefix so far
  float ratio;          // p(y) |J| / p(x) of the prefix so far (MIS between the two directions)
  float prev_pos[3];    // the offset's previous vertex (origin of the ray to its current vertex)
  float last_pdf;       // the offset's own solid-angle pdf of that ray's direction (0: delta)
  float dir[3];         // direction of the ray to the current vertex
  int mode;             // GPT_MODE_*
  unsigned int prim;    // current vertex (TRACE) as Embree found it; GDR_INVALID_ID for a miss
  float b1, b2;
  float t;
  int visible;          // RECONNECTING: the reconnection segment was unoccluded
  int last_delta;       // the ray to the current vertex left a delta lobe
  int glossy_next_only; // TRACE: the shift holds only if the current vertex is glossy
  GbdptSums mis;        // G-BDPT: the offset's own bidirectional MIS sums
} GptOffsetState;
