// Host/device overlap by batches (pt's paths, G-PT's groups): a chunk's items are split into
// consecutive ranges, one a batch with its own queues, states and command queue, and the batches
// are stepped in turn, so that the device works on one while the host traces the other's rays.
// Each item is one batch's, so the images do not depend on the split.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace gdr {

// Batches a chunk of `capacity` items runs: `wanted`, or 1 where a batch would hold fewer than
// `min_items` (launches and Embree's calls too small to pay).
inline int batch_count(size_t capacity, int wanted, size_t min_items) {
  return wanted > 1 && capacity >= min_items * size_t(wanted) ? wanted : 1;
}

// The items a batch holds at most: `capacity` split over `batches`.
inline size_t batch_capacity(size_t capacity, int batches) {
  return (capacity + size_t(batches) - 1) / size_t(batches);
}

// The items [first, first + count) of batch i of `batches` over the chunk's [chunk_first,
// + chunk_count): consecutive ranges of ceil(chunk_count / batches); count 0 past the end.
struct BatchRange {
  uint32_t first, count;
};
inline BatchRange batch_range(uint32_t chunk_first, uint32_t chunk_count, size_t batches, size_t i) {
  const uint32_t per = (chunk_count + uint32_t(batches) - 1) / uint32_t(batches);
  const uint32_t start = uint32_t(i) * per;
  return {chunk_first + start, start < chunk_count ? std::min(per, chunk_count - start) : 0};
}

// Steps every batch not `done` in turn until none is left.
template <class Batches, class Done, class Step>
void step_in_turn(Batches& batches, Done done, Step step) {
  for (bool busy = true; busy;) {
    busy = false;
    for (auto& b : batches) {
      if (done(b)) continue;
      step(b);
      busy = true;
    }
  }
}

}  // namespace gdr
