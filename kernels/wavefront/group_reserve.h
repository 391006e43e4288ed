// Appending to device queues from a work-group: the group's items count their entries in local
// memory and the group reserves its range of each queue with one atomic on the queue's counter,
// instead of one atomic per item. On a CPU device every item's atomic on a shared counter moves
// the counter's cache line between cores (about 40% of the path tracer's shading time went
// there); on a GPU it is the usual aggregation of global atomics.
//
// Every item of the group must reach the call (it holds barriers): kernels compute whether an item
// is in range instead of returning early, and items with nothing to append want 0 slots.
#pragma once

// The most queues one call reserves in, and the local memory a kernel declares for it:
// __local uint scratch[GROUP_RESERVE_SCRATCH].
#define GROUP_RESERVE_MAX 4
#define GROUP_RESERVE_SCRATCH (2 * GROUP_RESERVE_MAX)

// For queues i < n (counters[which[i]] counts the entries written so far), this item wants slots[i]
// entries; on return slots[i] is the first of them (an unused value where it wanted none).
__attribute__((always_inline)) inline void group_reserve(__local uint* scratch, __global uint* counters, const uint* which, int n, uint* slots) {
  if (get_local_id(0) == 0) {
    for (int i = 0; i < GROUP_RESERVE_MAX; ++i) scratch[i] = 0u;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  uint offset[GROUP_RESERVE_MAX];
  for (int i = 0; i < n; ++i) offset[i] = slots[i] ? atomic_add(&scratch[i], slots[i]) : 0u;
  barrier(CLK_LOCAL_MEM_FENCE);
  if (get_local_id(0) == 0) {
    for (int i = 0; i < n; ++i) {
      scratch[GROUP_RESERVE_MAX + i] = scratch[i] ? atomic_add(&counters[which[i]], scratch[i]) : 0u;
    }
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  for (int i = 0; i < n; ++i) slots[i] = scratch[GROUP_RESERVE_MAX + i] + offset[i];
}
