// Data-parallel primitives on the device (kernels/wavefront/scan.cl), shared by the stages that
// compact, route and sort work: an exclusive prefix sum, compaction, and a counting sort by key
// that is stable (each key's items in index order) and so the same on every run and device.
#pragma once
#include <deque>

#include "device/context.h"

namespace gdr {

class DevicePrimitives {
 public:
  explicit DevicePrimitives(Context& context);

  // data[0, n) becomes its exclusive prefix sum; returns the total.
  cl_uint exclusive_scan(Buffer<cl_uint>& data, size_t n);

  // out gets items[i] for every i < n with flags[i] != 0, in order; returns their count.
  // `offsets`: scratch of n entries.
  cl_uint compact(const Buffer<cl_uint>& flags, const Buffer<cl_uint>& items, size_t n, Buffer<cl_uint>& offsets,
                  Buffer<cl_uint>& out);

  // out gets the indices i < n with keys[i] == key, in order; returns their count. `offsets`:
  // scratch of n entries.
  cl_uint select_key(const Buffer<cl_uint>& keys, size_t n, cl_uint key, Buffer<cl_uint>& offsets,
                     Buffer<cl_uint>& out);

  // Sorts the indices i < n by keys[i] (keys >= buckets are left out): sorted[starts[k],
  // starts[k + 1]) lists key k's indices in ascending order. `starts` has buckets + 1 entries;
  // returns how many indices were sorted.
  cl_uint sort_by_key(const Buffer<cl_uint>& keys, size_t n, cl_uint buckets, Buffer<cl_uint>& starts,
                      Buffer<cl_uint>& sorted);

 private:
  cl_uint scan_level(Buffer<cl_uint>& data, size_t n, size_t level);

  Context& ctx_;
  Kernel scan_blocks_, scan_add_, compact_, key_flags_, key_scatter_, count_, scatter_, order_;
  std::deque<Buffer<cl_uint>> sums_;  // block sums per level of the scan (a deque: growing keeps references)
  Buffer<cl_uint> cursor_;
};

}  // namespace gdr
