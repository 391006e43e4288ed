#include "render/wavefront/primitives.h"

#include "shared/scan_block.h"

namespace gdr {
namespace {

constexpr const char* kProgram = "wavefront/scan.cl";

size_t blocks_of(size_t n) { return (n + SCAN_BLOCK - 1) / SCAN_BLOCK; }

}  // namespace

DevicePrimitives::DevicePrimitives(Context& ctx)
    : ctx_(ctx),
      scan_blocks_(ctx.program(kProgram)->kernel("scan_blocks")),
      scan_add_(ctx.program(kProgram)->kernel("scan_add")),
      compact_(ctx.program(kProgram)->kernel("compact_scatter")),
      keys_flags_(ctx.program(kProgram)->kernel("keys_flags")),
      keys_scatter_(ctx.program(kProgram)->kernel("keys_scatter")),
      keys_starts_(ctx.program(kProgram)->kernel("keys_starts")),
      count_(ctx.program(kProgram)->kernel("sort_count")),
      scatter_(ctx.program(kProgram)->kernel("sort_scatter")),
      order_(ctx.program(kProgram)->kernel("sort_order_buckets")) {}

cl_uint DevicePrimitives::scan_level(Buffer<cl_uint>& data, size_t n, size_t level, bool read_total) {
  const size_t blocks = blocks_of(n);
  if (sums_.size() <= level) sums_.resize(level + 1);
  if (sums_[level].size() < blocks) sums_[level] = Buffer<cl_uint>(ctx_, blocks);
  Buffer<cl_uint>& sums = sums_[level];
  scan_blocks_.args(data, cl_uint(n), sums).run(blocks * SCAN_GROUP, SCAN_GROUP);
  cl_uint total = 0;
  if (blocks == 1) {
    if (read_total) sums.read(&total, 1);
    return total;
  }
  total = scan_level(sums, blocks, level + 1, read_total);
  scan_add_.args(data, cl_uint(n), sums).run(n);
  return total;
}

cl_uint DevicePrimitives::exclusive_scan(Buffer<cl_uint>& data, size_t n) {
  return n == 0 ? 0 : scan_level(data, n, 0, true);
}

cl_uint DevicePrimitives::compact(const Buffer<cl_uint>& flags, const Buffer<cl_uint>& items, size_t n,
                                  Buffer<cl_uint>& offsets, Buffer<cl_uint>& out) {
  if (n == 0) return 0;
  flags.copy_to(offsets, n);
  cl_uint count = exclusive_scan(offsets, n);
  compact_.args(flags, offsets, items, cl_uint(n), out).run(n);
  return count;
}

std::vector<cl_uint> DevicePrimitives::select_keys(const Buffer<cl_uint>& keys, size_t n,
                                                   const Buffer<cl_uint>& key_buffer, Buffer<cl_uint>& offsets,
                                                   Buffer<cl_uint>& out) {
  const size_t count = key_buffer.size();
  std::vector<cl_uint> starts(count + 1, 0u);
  if (n == 0 || count == 0) return starts;
  if (starts_.size() < count + 1) starts_ = Buffer<cl_uint>(ctx_, count + 1);
  keys_flags_.args(keys, cl_uint(n), key_buffer, cl_uint(count), offsets).run(n);
  scan_level(offsets, count * n + 1, 0, false);
  keys_scatter_.args(keys, cl_uint(n), key_buffer, cl_uint(count), offsets, out).run(n);
  keys_starts_.args(offsets, cl_uint(n), cl_uint(count), starts_).run(count + 1);
  starts_.read(starts.data(), count + 1);
  return starts;
}

cl_uint DevicePrimitives::sort_by_key(const Buffer<cl_uint>& keys, size_t n, cl_uint buckets, Buffer<cl_uint>& starts,
                                      Buffer<cl_uint>& sorted) {
  starts.fill(0u);
  if (cursor_.size() < buckets) cursor_ = Buffer<cl_uint>(ctx_, buckets);
  cursor_.fill(0u);
  if (n > 0) count_.args(keys, cl_uint(n), buckets, starts).run(n);
  cl_uint total = exclusive_scan(starts, size_t(buckets) + 1);
  if (n > 0) scatter_.args(keys, cl_uint(n), buckets, starts, cursor_, sorted).run(n);
  order_.args(starts, buckets, sorted).run(buckets);
  return total;
}

}  // namespace gdr
