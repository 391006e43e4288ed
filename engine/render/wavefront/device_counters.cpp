#include "render/wavefront/device_counters.h"

#include <stdexcept>

namespace gdr {

namespace {
const std::vector<const char*>& checked_list(const std::vector<const char*>& names) {
  if (names.size() > GDR_COUNTER_STRIDE) throw std::logic_error("a counter list longer than GDR_COUNTER_STRIDE");
  return names;
}
}  // namespace

DeviceCounters::DeviceCounters(Context& ctx, std::vector<const char*> names)
    : buffer_(ctx, size_t{GDR_COUNTER_STRIDE} * (1 + GDR_COUNTER_SHARDS)),
      names_(checked_list(names)),
      last_(names_.size(), 0),
      totals_(names_.size(), 0) {}

const std::vector<cl_uint>& DeviceCounters::read() {
  const std::vector<cl_uint> copies = buffer_.read();
  for (size_t i = 0; i < last_.size(); ++i) {
    cl_uint v = 0;
    for (size_t c = 0; c <= GDR_COUNTER_SHARDS; ++c) v += copies[c * GDR_COUNTER_STRIDE + i];
    last_[i] = v;
    totals_[i] += v;
  }
  return last_;
}

void DeviceCounters::report(Stats* stats) {
  for (size_t i = 0; i < names_.size(); ++i) {
    if (stats && names_[i][0] != '\0' && totals_[i] != 0) stats->add_count(names_[i], totals_[i]);
    totals_[i] = 0;
  }
}

}  // namespace gdr
