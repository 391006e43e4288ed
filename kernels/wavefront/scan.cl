// Data-parallel primitives over uint arrays, for the wavefront stages that route, compact and
// sort work (engine/render/wavefront/primitives.h): an exclusive prefix sum in blocks of
// SCAN_BLOCK items (each block scanned in local memory, the block sums scanned the same way and
// added back), the compaction it enables, and a counting sort by key whose buckets are then put
// in index order, so that the result does not depend on the order atomics ran in.
#include "shared/scan_block.h"

// Position of block item i in local memory: one word of padding every 32, so that neither the
// coalesced copies (consecutive items) nor the runs (a stride of SCAN_RUN) meet in a GPU's banks.
#define SCAN_AT(i) ((i) + ((i) >> 5))

// Work group g scans items [g * SCAN_BLOCK, (g + 1) * SCAN_BLOCK) of data in place (exclusive)
// and writes their total to sums[g]. Launched with local size SCAN_GROUP. Each work item sums a
// run of SCAN_RUN items serially and only the runs' totals take the parallel scan's steps (on a
// CPU device, whose work items run one after another between barriers, those steps cost as many
// passes over the group as they have barriers); reads and writes stay coalesced through tmp.
__kernel void scan_blocks(__global uint* data, uint n, __global uint* sums) {
  __local uint tmp[SCAN_AT(SCAN_BLOCK)];
  __local uint runs[SCAN_GROUP];
  uint l = get_local_id(0), first = get_group_id(0) * SCAN_BLOCK;
  for (uint j = 0; j < SCAN_RUN; ++j) {
    uint i = first + j * SCAN_GROUP + l;
    tmp[SCAN_AT(j * SCAN_GROUP + l)] = i < n ? data[i] : 0u;
  }
  barrier(CLK_LOCAL_MEM_FENCE);
  uint total = 0u;
  for (uint j = 0; j < SCAN_RUN; ++j) {
    uint v = tmp[SCAN_AT(l * SCAN_RUN + j)];
    tmp[SCAN_AT(l * SCAN_RUN + j)] = total;
    total += v;
  }
  runs[l] = total;
  barrier(CLK_LOCAL_MEM_FENCE);
  // Hillis-Steele inclusive scan of the runs' totals: log2(SCAN_GROUP) steps.
  for (uint offset = 1; offset < SCAN_GROUP; offset <<= 1) {
    uint add = l >= offset ? runs[l - offset] : 0u;
    barrier(CLK_LOCAL_MEM_FENCE);
    runs[l] += add;
    barrier(CLK_LOCAL_MEM_FENCE);
  }
  uint before = runs[l] - total;
  for (uint j = 0; j < SCAN_RUN; ++j) tmp[SCAN_AT(l * SCAN_RUN + j)] += before;
  barrier(CLK_LOCAL_MEM_FENCE);
  for (uint j = 0; j < SCAN_RUN; ++j) {
    uint i = first + j * SCAN_GROUP + l;
    if (i < n) data[i] = tmp[SCAN_AT(j * SCAN_GROUP + l)];
  }
  if (l == SCAN_GROUP - 1) sums[get_group_id(0)] = runs[l];
}

// Adds the scanned block sums to the items of their blocks.
__kernel void scan_add(__global uint* data, uint n, __global const uint* sums) {
  uint i = get_global_id(0);
  if (i < n) data[i] += sums[i / SCAN_BLOCK];
}

// Compaction: item i with flags[i] != 0 goes to out[offsets[i]] (offsets: the exclusive scan of
// the flags), keeping the items' order.
__kernel void compact_scatter(__global const uint* flags, __global const uint* offsets, __global const uint* items,
                              uint n, __global uint* out) {
  uint i = get_global_id(0);
  if (i < n && flags[i]) out[offsets[i]] = items[i];
}

// Selection by several keys at once (key_list[t], t < key_count), step 1: flags[t n + i] = 1 where
// keys[i] is key t, and the entry past them 0 (its scan is the total).
__kernel void keys_flags(__global const uint* keys, uint n, __global const uint* key_list, uint key_count,
                         __global uint* flags) {
  uint i = get_global_id(0);
  if (i == 0) flags[key_count * n] = 0u;
  if (i >= n) return;
  uint k = keys[i];
  for (uint t = 0; t < key_count; ++t) flags[t * n + i] = k == key_list[t] ? 1u : 0u;
}

// Step 2 (offsets: the scanned flags): out lists key t's indices in order from offsets[t n] on.
__kernel void keys_scatter(__global const uint* keys, uint n, __global const uint* key_list, uint key_count,
                           __global const uint* offsets, __global uint* out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  uint k = keys[i];
  for (uint t = 0; t < key_count; ++t) {
    if (k == key_list[t]) out[offsets[t * n + i]] = i;
  }
}

// Step 3: starts[t] = offsets[t n], t <= key_count (starts[key_count]: the total).
__kernel void keys_starts(__global const uint* offsets, uint n, uint key_count, __global uint* starts) {
  uint t = get_global_id(0);
  if (t <= key_count) starts[t] = offsets[t * n];
}

// Counting sort by key, step 1: how many items each key has (keys >= buckets are left out).
__kernel void sort_count(__global const uint* keys, uint n, uint buckets, __global uint* counts) {
  uint i = get_global_id(0);
  if (i >= n || keys[i] >= buckets) return;
  atomic_inc(&counts[keys[i]]);
}

// Step 2, after the exclusive scan of the counts (buckets + 1 of them, the last 0) into starts:
// item indices into their buckets (cursor: zeroed, one per bucket).
__kernel void sort_scatter(__global const uint* keys, uint n, uint buckets, __global const uint* starts,
                           __global uint* cursor, __global uint* sorted) {
  uint i = get_global_id(0);
  if (i >= n || keys[i] >= buckets) return;
  uint k = keys[i];
  sorted[starts[k] + atomic_inc(&cursor[k])] = i;
}

// Step 3: each bucket's indices in ascending order (insertion sort: buckets are small), so the
// sort is stable and deterministic.
__kernel void sort_order_buckets(__global const uint* starts, uint buckets, __global uint* sorted) {
  uint b = get_global_id(0);
  if (b >= buckets) return;
  uint lo = starts[b], hi = starts[b + 1];
  for (uint i = lo + 1; i < hi; ++i) {
    uint v = sorted[i], j = i;
    for (; j > lo && sorted[j - 1] > v; --j) sorted[j] = sorted[j - 1];
    sorted[j] = v;
  }
}
