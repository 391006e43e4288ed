// Which passes of a render a process traces when several share it (cluster/ranks.h): rank r of N
// traces passes r, r + N, r + 2N, ... of the whole image. Every sample is keyed by its pass
// index (the counter-based RNG), so N ranks draw exactly the samples one process would, and
// passes of the same image take the same time: no rank waits for an uneven share. State that
// is not additive over passes follows the pass index too (pass i is the same whichever rank
// traces it).
#pragma once

namespace gdr {

struct PassSchedule {
  int rank = 0, ranks = 1;

  static PassSchedule of_this_process();

  bool traces(int pass) const { return pass % ranks == rank; }
  // Passes this rank traces among [0, passes).
  int held(int passes) const { return passes > rank ? (passes - 1 - rank) / ranks + 1 : 0; }
  // Those of them with parity `parity` (0: even pass indices, 1: odd).
  int held(int passes, int parity) const {
    const int k = held(passes);  // this rank's passes are rank + j * ranks, j in [0, k)
    if (ranks % 2 == 0) return rank % 2 == parity ? k : 0;
    const int first = ((parity - rank) % 2 + 2) % 2;  // the parity of j that gives `parity`
    return first == 0 ? (k + 1) / 2 : k / 2;
  }
};

}  // namespace gdr
