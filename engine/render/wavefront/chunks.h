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

// Calls trace(first, count) for consecutive ranges covering [0, items).
template <class F>
void for_each_chunk(uint32_t items, size_t capacity, F&& trace) {
  for (uint32_t first = 0; first < items; first += uint32_t(capacity)) {
    trace(first, std::min<uint32_t>(uint32_t(capacity), items - first));
  }
}

}  // namespace gdr
