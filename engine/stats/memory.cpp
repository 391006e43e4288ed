#include "stats/memory.h"

#include <sys/resource.h>

namespace gdr {

uint64_t peak_resident_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0 || u.ru_maxrss < 0) return 0;
  return uint64_t(u.ru_maxrss) * 1024;  // Linux reports kilobytes
}

}  // namespace gdr
