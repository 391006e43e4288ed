// The chunk loop of a wavefront pass: the image's paths are traced in chunks of at most
// `capacity` paths in flight, which bounds the queues' memory.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace gdr {

// Paths in flight per chunk: at most `max_in_flight`, at most one per pixel.
inline size_t chunk_capacity(size_t max_in_flight, int width, int height) {
  return std::min(max_in_flight, size_t(width) * size_t(height));
}

// On a CPU device a chunk holds at most this many paths (or groups of paths): their states then
// stay in the last-level cache from one kernel or Embree call to the next. A GPU wants its
// launches large. Only for integrators whose image does not depend on the chunks (a merging
// chunk's photons are its own light subpaths).
constexpr size_t kCpuMaxInFlight = size_t(1) << 14;

// chunk_capacity with kCpuMaxInFlight's bound on a CPU device; `in_flight` > 0 sets it instead.
inline size_t device_chunk_capacity(size_t max_in_flight, bool cpu, size_t in_flight, int width, int height) {
  if (in_flight > 0) return chunk_capacity(in_flight, width, height);
  return chunk_capacity(cpu ? std::min(max_in_flight, kCpuMaxInFlight) : max_in_flight, width, height);
}

// Calls trace(first, count) for consecutive ranges covering [0, items).
template <class F>
void for_each_chunk(uint32_t items, size_t capacity, F&& trace) {
  for (uint32_t first = 0; first < items; first += uint32_t(capacity)) {
    trace(first, std::min<uint32_t>(uint32_t(capacity), items - first));
  }
}

}  // namespace gdr
