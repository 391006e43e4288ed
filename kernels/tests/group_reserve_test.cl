// wavefront/group_reserve.h and wavefront/counter_shard.h for the host tests.
#include "wavefront/counter_shard.h"
#include "wavefront/group_reserve.h"

// Item i < count wants (i * 7) % 4 entries of queue a (counter 0) and one of queue b (counter 1)
// where i % 3 == 0, writes its index into them, and counts itself in counter 2 of its
// work-group's copy of the list.
__kernel void group_reserve_fill(uint count, __global uint* counters, __global uint* queue_a, __global uint* queue_b) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint i = get_global_id(0);
  uint want_a = i < count ? (i * 7u) % 4u : 0u, want_b = i < count && i % 3u == 0u;
  const uint which[2] = {0u, 1u};
  uint slots[2] = {want_a, want_b};
  group_reserve(scratch, counters, which, 2, slots);
  for (uint j = 0; j < want_a; ++j) queue_a[slots[0] + j] = i;
  if (want_b) queue_b[slots[1]] = i;
  if (i < count) atomic_inc(&counter_shard(counters)[2]);
}
