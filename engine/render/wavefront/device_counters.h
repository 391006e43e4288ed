// The counters one integrator's kernels increment, named once in kernels/shared (the X-macro
// lists PT_COUNTERS, GPT_COUNTERS, ...): zeroed before a step, read once after it, and their
// running totals reported to the stats under those names. The buffer holds the list and its
// GDR_COUNTER_SHARDS copies for stats counters (shared/counters.h); a counter's value is their sum.
#pragma once
#include <cstdint>
#include <vector>

#include "device/context.h"
#include "shared/counters.h"

namespace gdr {

// The stats names of a counter list: GDR_COUNTER_NAMES(PT_COUNTERS).
#define GDR_COUNTER_NAMES(LIST) std::vector<const char*>{LIST(GDR_COUNTER_STAT)}

class DeviceCounters {
 public:
  DeviceCounters(Context& context, std::vector<const char*> names);

  Buffer<cl_uint>& buffer() { return buffer_; }  // the kernels' `counters` argument
  void reset() { buffer_.fill(0u); }
  // This step's values (one read from the device); they are added to the totals.
  const std::vector<cl_uint>& read();
  cl_uint operator[](int id) const { return last_[id]; }
  // Adds the totals of the named counters to `stats` (if any) and starts new totals.
  void report(Stats* stats);

 private:
  Buffer<cl_uint> buffer_;
  std::vector<const char*> names_;
  std::vector<cl_uint> last_;
  std::vector<uint64_t> totals_;
};

}  // namespace gdr
