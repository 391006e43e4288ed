// The device primitives (render/wavefront/primitives.h) against their definitions on the host:
// exclusive scan, compaction, selection by key and the stable sort by key, at sizes around the scan's block of
// 256 and across its levels (256^2 items need two).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "render/wavefront/primitives.h"
#include "support/devices.h"

namespace gdr {
namespace {

const size_t kSizes[] = {1, 2, 255, 256, 257, 1000, 65536, 65537, 300000};

std::vector<cl_uint> random_values(size_t n, cl_uint below, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<cl_uint> d(0, below - 1);
  std::vector<cl_uint> v(n);
  for (cl_uint& x : v) x = d(rng);
  return v;
}

TEST(DevicePrimitives, ExclusiveScan) {
  Context& ctx = test::default_context();
  DevicePrimitives prim(ctx);
  for (size_t n : kSizes) {
    std::vector<cl_uint> v = random_values(n, 8, uint32_t(n));
    Buffer<cl_uint> b(ctx, v);
    cl_uint total = prim.exclusive_scan(b, n);
    std::vector<cl_uint> want(n);
    std::exclusive_scan(v.begin(), v.end(), want.begin(), cl_uint(0));
    EXPECT_EQ(b.read(), want) << n << " items";
    EXPECT_EQ(total, std::accumulate(v.begin(), v.end(), cl_uint(0))) << n << " items";
  }
}

TEST(DevicePrimitives, CompactKeepsOrder) {
  Context& ctx = test::default_context();
  DevicePrimitives prim(ctx);
  for (size_t n : kSizes) {
    std::vector<cl_uint> flags = random_values(n, 2, uint32_t(n) + 1), items = random_values(n, 1u << 30, uint32_t(n) + 2);
    Buffer<cl_uint> f(ctx, flags), it(ctx, items), offsets(ctx, n), out(ctx, n);
    cl_uint count = prim.compact(f, it, n, offsets, out);
    std::vector<cl_uint> want;
    for (size_t i = 0; i < n; ++i)
      if (flags[i]) want.push_back(items[i]);
    ASSERT_EQ(count, want.size()) << n << " items";
    std::vector<cl_uint> got = out.read();
    got.resize(count);
    EXPECT_EQ(got, want) << n << " items";
  }
}

// Keys 0..4 of which three are selected (one of them absent from the items: an empty range);
// the others are left out.
TEST(DevicePrimitives, SelectKeysKeepsOrder) {
  Context& ctx = test::default_context();
  DevicePrimitives prim(ctx);
  const std::vector<cl_uint> selected = {3u, 0u, 7u};
  Buffer<cl_uint> key_buffer(ctx, selected);
  for (size_t n : kSizes) {
    std::vector<cl_uint> keys = random_values(n, 5, uint32_t(n) + 4);
    Buffer<cl_uint> k(ctx, keys), offsets(ctx, selected.size() * n + 1), out(ctx, std::max<size_t>(n, 1));
    std::vector<cl_uint> starts = prim.select_keys(k, n, key_buffer, offsets, out);
    ASSERT_EQ(starts.size(), selected.size() + 1);
    std::vector<cl_uint> got = out.read();
    cl_uint start = 0;
    for (size_t t = 0; t < selected.size(); ++t) {
      std::vector<cl_uint> want;
      for (size_t i = 0; i < n; ++i)
        if (keys[i] == selected[t]) want.push_back(cl_uint(i));
      ASSERT_EQ(starts[t], start) << n << " items, key " << selected[t];
      ASSERT_EQ(starts[t + 1] - starts[t], want.size()) << n << " items, key " << selected[t];
      EXPECT_EQ(std::vector<cl_uint>(got.begin() + starts[t], got.begin() + starts[t + 1]), want)
          << n << " items, key " << selected[t];
      start = starts[t + 1];
    }
  }
}

// Keys include some at or above the bucket count, which are left out.
TEST(DevicePrimitives, SortByKeyIsStable) {
  Context& ctx = test::default_context();
  DevicePrimitives prim(ctx);
  for (size_t n : kSizes) {
    const cl_uint buckets = cl_uint(std::max<size_t>(1, n / 3));
    std::vector<cl_uint> keys = random_values(n, buckets + buckets / 10 + 1, uint32_t(n) + 3);
    Buffer<cl_uint> k(ctx, keys), starts(ctx, size_t(buckets) + 1), sorted(ctx, n);
    cl_uint count = prim.sort_by_key(k, n, buckets, starts, sorted);
    std::vector<cl_uint> want;
    for (size_t i = 0; i < n; ++i)
      if (keys[i] < buckets) want.push_back(cl_uint(i));
    std::stable_sort(want.begin(), want.end(), [&](cl_uint a, cl_uint b) { return keys[a] < keys[b]; });
    ASSERT_EQ(count, want.size()) << n << " items";
    std::vector<cl_uint> got = sorted.read(), s = starts.read();
    got.resize(count);
    EXPECT_EQ(got, want) << n << " items";
    for (cl_uint b = 0; b < buckets; ++b) {
      for (cl_uint i = s[b]; i < s[b + 1]; ++i) ASSERT_EQ(keys[got[i]], b) << n << " items, bucket " << b;
    }
    EXPECT_EQ(s[buckets], count);
  }
}

}  // namespace
}  // namespace gdr
