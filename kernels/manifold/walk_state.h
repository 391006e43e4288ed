// A walk's iteration state: its words in the structure-of-arrays buffer (shared/manifold_types.h)
// and the private copy a kernel works on. Each kernel reads and writes only the fields it needs:
// the re-trace touches the proposal alone, the proposal step writes only its trace fields.
#pragma once
#include "shared/manifold_types.h"

typedef struct ManifoldState {
  int phase, iterations;
  float beta, error;
  int accepted, chain_reaches;
  int traced, trace_status, proposal_reaches;
  float chain_end[3], proposal_end[3];
  GdrManifoldPoint chain[MANIFOLD_MAX_CHAIN], proposal[MANIFOLD_MAX_CHAIN];
} ManifoldState;

// The state buffer of one solve: field f of walk w.
#define MANIFOLD_WORD(s, f) (s).words[(size_t)(f) * (s).capacity + (s).walk]
typedef struct ManifoldStateRef {
  __global uint* words;
  uint capacity, walk;
} ManifoldStateRef;

inline ManifoldStateRef manifold_state_ref(__global uint* words, uint capacity, uint walk) {
  ManifoldStateRef s = {words, capacity, walk};
  return s;
}

inline int state_int(ManifoldStateRef s, int f) { return (int)MANIFOLD_WORD(s, f); }
inline float state_float(ManifoldStateRef s, int f) { return as_float(MANIFOLD_WORD(s, f)); }
inline void set_state_int(ManifoldStateRef s, int f, int v) { MANIFOLD_WORD(s, f) = (uint)v; }
inline void set_state_float(ManifoldStateRef s, int f, float v) { MANIFOLD_WORD(s, f) = as_uint(v); }

inline GdrManifoldPoint state_point(ManifoldStateRef s, int f) {
  GdrManifoldPoint p = {MANIFOLD_WORD(s, f), state_float(s, f + 1), state_float(s, f + 2)};
  return p;
}
inline void set_state_point(ManifoldStateRef s, int f, GdrManifoldPoint p) {
  MANIFOLD_WORD(s, f) = p.prim;
  set_state_float(s, f + 1, p.b1);
  set_state_float(s, f + 2, p.b2);
}
inline void set_state_float3(ManifoldStateRef s, int f, float3 v) {
  set_state_float(s, f, v.x);
  set_state_float(s, f + 1, v.y);
  set_state_float(s, f + 2, v.z);
}

// The proposal's trace fields (written by the proposal step and the re-trace).
inline void store_trace(ManifoldStateRef s, const ManifoldState* st) {
  set_state_int(s, MANIFOLD_STATE_TRACED, st->traced);
  set_state_int(s, MANIFOLD_STATE_TRACE_STATUS, st->trace_status);
  set_state_int(s, MANIFOLD_STATE_PROPOSAL_REACHES, st->proposal_reaches);
}

// The walk's control and its accepted chain (`count` vertices); with `proposal`, the traced
// proposal too.
inline void load_state(ManifoldStateRef s, int count, int proposal, ManifoldState* st) {
  st->phase = state_int(s, MANIFOLD_STATE_PHASE);
  st->iterations = state_int(s, MANIFOLD_STATE_ITERATIONS);
  st->beta = state_float(s, MANIFOLD_STATE_BETA);
  st->error = state_float(s, MANIFOLD_STATE_ERROR);
  st->accepted = state_int(s, MANIFOLD_STATE_ACCEPTED);
  st->chain_reaches = state_int(s, MANIFOLD_STATE_CHAIN_REACHES);
  st->traced = state_int(s, MANIFOLD_STATE_TRACED);
  st->trace_status = state_int(s, MANIFOLD_STATE_TRACE_STATUS);
  st->proposal_reaches = state_int(s, MANIFOLD_STATE_PROPOSAL_REACHES);
  for (int k = 0; k < 3; ++k) st->chain_end[k] = state_float(s, MANIFOLD_STATE_CHAIN_END + k);
  for (int k = 0; k < count; ++k) st->chain[k] = state_point(s, MANIFOLD_STATE_CHAIN + 3 * k);
  if (!proposal) return;
  for (int k = 0; k < 3; ++k) st->proposal_end[k] = state_float(s, MANIFOLD_STATE_PROPOSAL_END + k);
  for (int k = 0; k < count; ++k) st->proposal[k] = state_point(s, MANIFOLD_STATE_PROPOSAL + 3 * k);
}

// The control and the accepted chain (the proposal is the re-trace's to write).
inline void store_state(ManifoldStateRef s, int count, const ManifoldState* st) {
  set_state_int(s, MANIFOLD_STATE_PHASE, st->phase);
  set_state_int(s, MANIFOLD_STATE_ITERATIONS, st->iterations);
  set_state_float(s, MANIFOLD_STATE_BETA, st->beta);
  set_state_float(s, MANIFOLD_STATE_ERROR, st->error);
  set_state_int(s, MANIFOLD_STATE_ACCEPTED, st->accepted);
  set_state_int(s, MANIFOLD_STATE_CHAIN_REACHES, st->chain_reaches);
  for (int k = 0; k < 3; ++k) set_state_float(s, MANIFOLD_STATE_CHAIN_END + k, st->chain_end[k]);
  for (int k = 0; k < count; ++k) set_state_point(s, MANIFOLD_STATE_CHAIN + 3 * k, st->chain[k]);
}
