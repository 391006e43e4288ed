// The copy of an integrator's counter list that this work-group's stats counters go to
// (shared/counters.h): only counters the host sums, never a queue's slot count.
#pragma once
#include "shared/counters.h"

inline __global uint* counter_shard(__global uint* counters) {
  return counters + GDR_COUNTER_STRIDE * (1u + (uint)get_group_id(0) % GDR_COUNTER_SHARDS);
}
