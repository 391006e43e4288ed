// Device counters (atomic_inc in kernels, read by the host after a step). Each integrator lists
// its counters once, as X(ID, "stats name") with "" for counters that only steer the host loop:
// kernels get the IDs as an enum, the host the names under which the totals reach the stats
// (engine/render/wavefront/device_counters.h).
#pragma once

#define GDR_COUNTER_ENUM(id, stat) id,
#define GDR_COUNTER_STAT(id, stat) stat,

// A counter that only counts (a stats counter, never a queue's slot count) may be incremented in
// one of GDR_COUNTER_SHARDS copies of the list instead, chosen by work-group (counter_shard in
// kernels/wavefront/counter_shard.h): work-groups running at once on different cores then do not
// move one cache line back and forth. The host sums the copies into each counter's value. Copies
// lie GDR_COUNTER_STRIDE counters apart (no list is longer).
#define GDR_COUNTER_SHARDS 8
#define GDR_COUNTER_STRIDE 64
