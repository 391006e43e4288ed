// Data-parallel primitives on the device (kernels/wavefront/scan.cl), shared by the stages that
// compact, route and sort work: an exclusive prefix sum, compaction, and a counting sort by key
// that is stable (each key's items in index order) and so the same on every run and device.
#pragma once
#include <deque>
#include <vector>

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

  // For each key t < key_list.size(), the indices i < n with keys[i] == key_list[t], in order, at
  // out[starts[t], starts[t + 1]); returns starts (key_list.size() + 1 entries), with one read
  // from the device for all keys. `key_buffer`: key_list on the device (its size entries);
  // `offsets`: scratch of key_list.size() * n + 1 entries.
  std::vector<cl_uint> select_keys(const Buffer<cl_uint>& keys, size_t n, const Buffer<cl_uint>& key_buffer,
                                   Buffer<cl_uint>& offsets, Buffer<cl_uint>& out);
  // Sorts the indices i < n by keys[i] (keys >= buckets are left out): sorted[starts[k],
  // starts[k + 1]) lists key k's indices in ascending order. `starts` has buckets + 1 entries;
  // returns how many indices were sorted.
  cl_uint sort_by_key(const Buffer<cl_uint>& keys, size_t n, cl_uint buckets, Buffer<cl_uint>& starts,
                      Buffer<cl_uint>& sorted);

 private:
  // The exclusive scan of data[0, n) at recursion level `level`; returns the total where
  // `read_total` (one read), else 0 (the total stays on the device).
  cl_uint scan_level(Buffer<cl_uint>& data, size_t n, size_t level, bool read_total);

  Context& ctx_;
  Kernel scan_blocks_, scan_add_, compact_, keys_flags_, keys_scatter_, keys_starts_, count_, scatter_, order_;
  Buffer<cl_uint> starts_;  // select_keys' result on the device
  std::deque<Buffer<cl_uint>> sums_;  // block sums per level of the scan (a deque: growing keeps references)
  Buffer<cl_uint> cursor_;
};

}  // namespace gdr
