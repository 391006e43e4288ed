// The process's peak resident memory, for the stats: on CPU devices the device's buffers live in
// it too; a discrete GPU's memory is not in it.
#pragma once
#include <cstdint>

namespace gdr {

// Peak resident set size of this process so far, in bytes (0 where the system does not say).
uint64_t peak_resident_bytes();

}  // namespace gdr
