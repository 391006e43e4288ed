#include "render/wavefront/device_counters.h"

namespace gdr {

DeviceCounters::DeviceCounters(Context& ctx, std::vector<const char*> names)
    : buffer_(ctx, names.size()), names_(std::move(names)), last_(names_.size(), 0), totals_(names_.size(), 0) {}

const std::vector<cl_uint>& DeviceCounters::read() {
  last_ = buffer_.read();
  for (size_t i = 0; i < last_.size(); ++i) totals_[i] += last_[i];
  return last_;
}

void DeviceCounters::report(Stats* stats) {
  for (size_t i = 0; i < names_.size(); ++i) {
    if (stats && names_[i][0] != '\0' && totals_[i] != 0) stats->add_count(names_[i], totals_[i]);
    totals_[i] = 0;
  }
}

}  // namespace gdr
