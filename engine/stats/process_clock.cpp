#include "stats/process_clock.h"

#include <chrono>

namespace gdr {
namespace {
const auto g_start = std::chrono::steady_clock::now();
}

double seconds_since_process_start() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - g_start).count();
}

}  // namespace gdr
