// FNV-1a: a stable 64-bit hash for cache keys (std::hash is not stable across builds).
#pragma once
#include <cstdint>
#include <string_view>

namespace gdr {

inline uint64_t fnv1a64(std::string_view data, uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : data) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace gdr
