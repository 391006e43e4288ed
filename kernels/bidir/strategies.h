// Which strategies a bidirectional path adds. By default all of them, each weighted by MIS;
// `--strategy s,t` shows one alone, unweighted; under multiplexing (Hachisuka et al. 2014,
// "Multiplexed Metropolis Light Transport"; pbrt-v4's MLTIntegrator) each path draws from its
// strategy block a length n of 1 .. max_depth segments and one of that length's strategies, and
// adds only that one, with its MIS weight; the Metropolis integrator divides by the two
// selection probabilities (bidir_selection_count). A path of n >= 2 segments has n + 1
// strategies: s = n + 1 - t light vertices for t = 1 .. n + 1 camera vertices (the pinhole is
// never hit, so t >= 1; t = 1 needs s >= 2); a path of one segment only s = 0, t = 2.
#pragma once
#include "sampling/path_sampler.h"
#include "shared/bidir_types.h"

inline int bidir_strategy_count(int segments) { return segments < 2 ? 1 : segments + 1; }

// The strategy of path length `segments` numbered i (0: s = 0).
inline int2 bidir_strategy_of(int segments, int i) {
  int t = segments + 1 - i;
  return (int2)(segments + 1 - t, t);
}

// The (s, t) the path of sampler ps adds, or (-1, -1) for all; max_depth: the longest path in
// segments (bounded under multiplexing).
inline int2 bidir_path_strategy(const GdrBidirOptions* o, const PathSampler* ps, int max_depth) {
  if (!o->multiplex) return (int2)(o->strategy_s, o->strategy_t);
  float4 u = sampler_block(ps, RNG_BLOCK_STRATEGY);
  int n = 1 + min((int)(u.x * (float)max_depth), max_depth - 1);
  int count = bidir_strategy_count(n);
  return bidir_strategy_of(n, min((int)(u.y * (float)count), count - 1));
}

// 1 / the probability with which a multiplexed path picked its strategy: lengths times that
// length's strategies.
inline float bidir_selection_count(int2 st, int max_depth) {
  return (float)max_depth * (float)bidir_strategy_count(st.x + st.y - 1);
}

inline void bidir_set_strategy(GdrBidirPathState* st, int2 shown) {
  st->shown_s = shown.x;
  st->shown_t = shown.y;
}

// The strategy (s light vertices, t camera vertices) is the path's one, or it adds all.
inline int bidir_strategy_shown(const GdrBidirPathState* st, int s, int t) {
  return st->shown_s < 0 || (st->shown_s == s && st->shown_t == t);
}

// Whether a subpath with `vertices` vertices (its camera or light point included) goes on: its
// strategy may need more of them.
inline int bidir_light_subpath_grows(const GdrBidirPathState* st, int vertices) {
  return st->shown_s < 0 || vertices < st->shown_s;
}
inline int bidir_camera_subpath_grows(const GdrBidirPathState* st, int vertices) {
  return st->shown_t < 0 || vertices < st->shown_t;
}
