// The device primitives (render/wavefront/primitives.h) against their definitions on the host:
// exclusive scan, compaction, selection by key and the stable sort by key, at sizes around a work
// item's run of 16, the scan's block of 4096 and across its levels (65537 items take two, 4096^2 + 1
// three: the scan alone takes those); the work-groups' reservations of queue slots
// (wavefront/group_reserve.h) and the stats counters' per-work-group copies (device_counters.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "render/wavefront/device_counters.h"
#include "render/wavefront/primitives.h"
#include "support/devices.h"

namespace gdr {
namespace {

const size_t kSizes[] = {1, 2, 15, 17, 255, 256, 257, 1000, 4095, 4096, 4097, 65536, 65537, 300000};

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
  std::vector<size_t> sizes(std::begin(kSizes), std::end(kSizes));
  sizes.push_back(size_t{4096} * 4096 + 1);
  for (size_t n : sizes) {
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

// Items of work-groups of 64 reserve slots in two queues at once (test kernel
// group_reserve_fill: item i wants (7 i) mod 4 of queue a and one of queue b where 3 divides i):
// the counters come to the totals, and every item finds its own entries, contiguous, in each
// queue, with no slot written twice or left out. A third counter, incremented in the work-groups'
// copies, sums to the item count.
TEST(DevicePrimitives, GroupReserveGivesEachItemItsOwnSlots) {
  Context& ctx = test::default_context();
  Kernel fill = ctx.program("tests/group_reserve_test.cl")->kernel("group_reserve_fill");
  for (size_t n : {size_t{1}, size_t{63}, size_t{64}, size_t{65}, size_t{1000}, size_t{100001}}) {
    size_t want_a = 0, want_b = 0;
    for (size_t i = 0; i < n; ++i) {
      want_a += (i * 7) % 4;
      want_b += i % 3 == 0;
    }
    DeviceCounters counters(ctx, {"", "", ""});
    counters.reset();
    const cl_uint unwritten = 0xFFFFFFFFu;
    Buffer<cl_uint> a(ctx, std::vector<cl_uint>(want_a + 1, unwritten)), b(ctx, std::vector<cl_uint>(want_b + 1, unwritten));
    fill.args(cl_uint(n), counters.buffer(), a, b).run(n, 64);
    const std::vector<cl_uint>& c = counters.read();
    ASSERT_EQ(c[0], want_a) << n << " items";
    ASSERT_EQ(c[1], want_b) << n << " items";
    EXPECT_EQ(c[2], n) << n << " items";
    std::vector<cl_uint> qa = a.read(), qb = b.read();
    EXPECT_EQ(qa[want_a], unwritten) << n << " items: a slot past the count was written";
    EXPECT_EQ(qb[want_b], unwritten) << n << " items: a slot past the count was written";
    // Queue a: runs of each item's index as long as it wanted, every item once.
    std::vector<size_t> seen(n, 0);
    for (size_t k = 0; k < want_a;) {
      cl_uint i = qa[k];
      ASSERT_LT(i, n) << n << " items: slot " << k << " of queue a";
      ASSERT_EQ(seen[i], 0u) << n << " items: item " << i << "'s entries are not contiguous";
      size_t run = 0;
      while (k < want_a && qa[k] == i) ++k, ++run;
      seen[i] = run;
      EXPECT_EQ(run, (size_t(i) * 7) % 4) << n << " items: item " << i;
    }
    std::vector<int> in_b(n, 0);
    for (size_t k = 0; k < want_b; ++k) {
      ASSERT_LT(qb[k], n) << n << " items: slot " << k << " of queue b";
      ASSERT_EQ(qb[k] % 3, 0u) << n << " items";
      ASSERT_EQ(in_b[qb[k]]++, 0) << n << " items: item " << qb[k] << " twice in queue b";
    }
  }
}

}  // namespace
}  // namespace gdr
