// The pass schedule splits a render's passes among ranks exactly: every pass is traced by one
// rank, and each rank's counts (all, and per parity: the halves of a gradient film) are those
// of the passes it traces.
#include <gtest/gtest.h>

#include "render/pass_schedule.h"

namespace gdr {
namespace {

TEST(PassSchedule, EveryPassIsTracedByExactlyOneRankAndTheCountsAreItsOwn) {
  for (int ranks = 1; ranks <= 7; ++ranks) {
    for (int passes = 0; passes <= 40; ++passes) {
      int total = 0, by_parity[2] = {0, 0};
      for (int rank = 0; rank < ranks; ++rank) {
        const PassSchedule s{rank, ranks};
        int mine = 0, mine_by_parity[2] = {0, 0};
        for (int i = 0; i < passes; ++i) {
          int owners = 0;
          for (int r = 0; r < ranks; ++r) owners += PassSchedule{r, ranks}.traces(i) ? 1 : 0;
          ASSERT_EQ(owners, 1) << "pass " << i << " of " << ranks << " ranks";
          if (s.traces(i)) ++mine, ++mine_by_parity[i % 2];
        }
        ASSERT_EQ(s.held(passes), mine) << "rank " << rank << " of " << ranks << ", " << passes << " passes";
        for (int p = 0; p < 2; ++p) {
          ASSERT_EQ(s.held(passes, p), mine_by_parity[p])
              << "rank " << rank << " of " << ranks << ", " << passes << " passes, parity " << p;
          by_parity[p] += s.held(passes, p);
        }
        total += s.held(passes);
      }
      EXPECT_EQ(total, passes);
      EXPECT_EQ(by_parity[0], (passes + 1) / 2);
      EXPECT_EQ(by_parity[1], passes / 2);
    }
  }
}

TEST(PassSchedule, AloneEveryPassIsTraced) {
  const PassSchedule s = PassSchedule::of_this_process();  // no MPI launcher in a test binary
  EXPECT_EQ(s.ranks, 1);
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(s.traces(i));
}

}  // namespace
}  // namespace gdr
