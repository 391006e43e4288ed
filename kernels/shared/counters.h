// Device counters (atomic_inc in kernels, read by the host after a step). Each integrator lists
// its counters once, as X(ID, "stats name") with "" for counters that only steer the host loop:
// kernels get the IDs as an enum, the host the names under which the totals reach the stats
// (engine/render/wavefront/device_counters.h).
#pragma once

#define GDR_COUNTER_ENUM(id, stat) id,
#define GDR_COUNTER_STAT(id, stat) stat,
