// The films' reductions: every rank's per-pixel sums, and its per-pixel moment sets, combined
// onto rank 0. Each call is a collective (every rank calls it, in the same order), a no-op for a
// single rank. Timed as `mpi/reduce` in the stats, the bytes each rank sends counted as
// `mpi/reduce_bytes`.
#pragma once
#include <vector>

#include "stats/stats.h"

namespace gdr::cluster {

// Sums `values` over the ranks: the totals on rank 0; other ranks' values are left as they were.
void sum_to_root(std::vector<float>& values, Stats* stats);

// Per value i: `passes` samples with the sum sum[i] and the summed squared deviations from their
// mean m2[i] (render/film.h: pass_estimate); interleaved RGB, three values a pixel.
struct Moments {
  int passes = 0;
  std::vector<float> sum, m2;
};

// Joins every rank's moments (disjoint sets of passes of the same values) on rank 0, by the
// pairwise update of Chan, Golub and LeVeque in double: squared deviations are not additive, a
// sum of them would leave out the spread between the ranks' means. Rank 0 ends with the totals
// (passes included); other ranks' moments are left as they were.
void combine_to_root(Moments& moments, Stats* stats);

// Two disjoint sets as one (what combine_to_root does for every pair it meets).
void combine_into(double& passes, double& sum, double& m2, double passes_b, double sum_b, double m2_b);

}  // namespace gdr::cluster
