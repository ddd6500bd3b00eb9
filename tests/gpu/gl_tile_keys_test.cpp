// The key engine of the compute tile rasterizers (gpu/compute/gl_tile_keys.hpp; docs/gpu.md "The
// compute tile rasterizer") on its own, against a CPU exclusive scan and std::stable_sort: the
// scan of the per-item counts, the sort by slot, the per-slot ranges, the work list and its
// indirect dispatch, at the sizes where the passes change shape (0, 1, a block of 1024 items and
// one either side, more than 65535 work groups) and with more keys than the capacity (the
// capacity path leaves keys out and reports the total, so the client can grow and redraw), and
// the client's half of that recovery (GlKeyCapacity).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "gpu/compute/gl_key_capacity.hpp"
#include "gpu/compute/gl_tile_keys.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_program.hpp"

namespace lfd::gpu {
namespace {

constexpr uint32_t kNoKey = 0xFFFFFFFFu;

std::vector<uint32_t> random_counts(size_t items, uint32_t seed, uint32_t most = 3) {
  std::mt19937 rng(seed);
  std::vector<uint32_t> counts(items);
  for (auto& c : counts) c = rng() % (most + 1);
  return counts;
}

// Each item's first key (the exclusive scan) and the total.
std::vector<uint32_t> exclusive_scan(const std::vector<uint32_t>& counts, uint64_t& total) {
  std::vector<uint32_t> first(counts.size());
  total = 0;
  for (size_t i = 0; i < counts.size(); ++i) {
    first[i] = uint32_t(total);
    total += counts[i];
  }
  return first;
}

// Uploads `counts` as the client's count pass would write them.
void upload_counts(GlTileKeys& tiles, const std::vector<uint32_t>& counts) {
  Buffer& buffer = tiles.counts(counts.size());
  if (!counts.empty()) buffer.upload(counts.data(), counts.size() * 4);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// The keys a client writes from the scanned first keys: item i's keys at first[i].., each a
// random slot below `slots`, the item as value (what tile_key_writer.glsl writes).
struct Keys {
  std::vector<uint32_t> slots, items;
};
Keys client_keys(const std::vector<uint32_t>& counts, uint32_t slots, uint32_t seed) {
  std::mt19937 rng(seed);
  Keys k;
  for (uint32_t item = 0; item < counts.size(); ++item)
    for (uint32_t n = 0; n < counts[item]; ++n) {
      k.slots.push_back(rng() % slots);
      k.items.push_back(item);
    }
  return k;
}

// std::stable_sort of the keys by slot, and each slot's range in the result.
struct Sorted {
  Keys keys;
  std::vector<std::pair<uint32_t, uint32_t>> ranges;
  std::vector<uint32_t> non_empty;
};
Sorted expected_sort(const Keys& keys, uint32_t slots) {
  std::vector<uint32_t> order(keys.slots.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys.slots[a] < keys.slots[b]; });
  Sorted s;
  s.ranges.assign(slots, {0u, 0u});
  for (uint32_t i = 0; i < order.size(); ++i) {
    const uint32_t slot = keys.slots[order[i]];
    s.keys.slots.push_back(slot);
    s.keys.items.push_back(keys.items[order[i]]);
    if (i == 0 || s.keys.slots[i - 1] != slot) {
      s.ranges[slot].first = i;
      s.non_empty.push_back(slot);
    }
    s.ranges[slot].second = i + 1;
  }
  return s;
}

// Compares the engine's sorted keys, ranges, work list and dispatch with `want`.
void expect_sorted(const GlTileKeys& tiles, const Sorted& want, uint32_t slots, const std::string& what) {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const size_t n = want.keys.slots.size();
  const auto keys = const_cast<GlTileKeys&>(tiles).keys().download_as<uint32_t>(n);
  const auto values = const_cast<GlTileKeys&>(tiles).values().download_as<uint32_t>(n);
  for (size_t i = 0; i < n; ++i) {
    ASSERT_EQ(keys[i], want.keys.slots[i]) << what << ": slot of key " << i;
    ASSERT_EQ(values[i], want.keys.items[i]) << what << ": item of key " << i << " (not stable?)";
  }
  const auto ranges = tiles.ranges().download_as<uint32_t>(size_t(slots) * 2);
  for (uint32_t s = 0; s < slots; ++s) {
    ASSERT_EQ(ranges[2 * s], want.ranges[s].first) << what << ": first key of slot " << s;
    ASSERT_EQ(ranges[2 * s + 1], want.ranges[s].second) << what << ": end key of slot " << s;
  }
  TileState state;
  tiles.state().download(&state, sizeof(state));
  ASSERT_EQ(state.work_count, want.non_empty.size()) << what << ": non-empty slots";
  std::vector<uint32_t> work = tiles.work().download_as<uint32_t>(std::max<size_t>(state.work_count, 1));
  work.resize(state.work_count);
  std::sort(work.begin(), work.end());
  EXPECT_EQ(work, want.non_empty) << what << ": the work list holds every non-empty slot once";
  // One group a slot, at most 65535 a row, rows enough for all.
  EXPECT_EQ(state.groups_x, std::min<uint32_t>(state.work_count, 65535u)) << what;
  EXPECT_EQ(state.groups_y, state.work_count == 0 ? 0u : (state.work_count + 65534u) / 65535u) << what;
  EXPECT_EQ(state.groups_z, 1u) << what;
}

// Scans `counts` (GlTileKeys::scan) and checks each item's first key and the total.
uint64_t expect_scan(GlTileKeys& tiles, const std::vector<uint32_t>& counts, const std::string& what) {
  uint64_t total = 0;
  const std::vector<uint32_t> want = exclusive_scan(counts, total);
  upload_counts(tiles, counts);
  EXPECT_EQ(tiles.scan(uint32_t(counts.size())), total) << what;
  if (!counts.empty()) {
    const auto got = tiles.counts(counts.size()).download_as<uint32_t>(counts.size());
    for (size_t i = 0; i < counts.size(); ++i) {
      if (got[i] == want[i]) continue;
      ADD_FAILURE() << what << ": first key of item " << i << " is " << got[i] << ", not " << want[i];
      break;
    }
  }
  return total;
}

TEST(GlTileKeys, SlotBitsHoldEverySlot) {
  EXPECT_EQ(slot_bits(1), 1);
  EXPECT_EQ(slot_bits(2), 1);
  EXPECT_EQ(slot_bits(3), 2);
  EXPECT_EQ(slot_bits(1024), 10);
  EXPECT_EQ(slot_bits(1025), 11);
  EXPECT_EQ(slot_bits(45u * 1824u), 17);
}

TEST(GlTileKeys, ScansCountsLikeTheCpuAcrossBlockEdges) {
  HeadlessContext context;
  GlTileKeys tiles;
  // A block is 1024 items (kTileScanBlockItems): one short, one, one over; 300000: 293 blocks.
  for (const size_t n : {size_t(0), size_t(1), size_t(1023), size_t(1024), size_t(1025), size_t(300000)})
    expect_scan(tiles, random_counts(n, uint32_t(n) + 3), "items " + std::to_string(n));
  // Every item without keys, and one item with many.
  expect_scan(tiles, std::vector<uint32_t>(1025, 0u), "no keys");
  expect_scan(tiles, {70000u}, "one item of 70000 keys");
}

TEST(GlTileKeys, ScansMoreThan65535WorkGroups) {
  // 65536 blocks and a few items: the scan's passes spread their groups over y.
  HeadlessContext context;
  GlTileKeys tiles;
  const size_t n = size_t(65536) * kTileScanBlockItems + 5;
  const uint64_t total = expect_scan(tiles, random_counts(n, 41, 1), "65536 blocks");
  EXPECT_GT(total, 0u);
}

TEST(GlTileKeys, SortsBySlotStablyAndFindsRangesLikeTheCpu) {
  HeadlessContext context;
  GlTileKeys tiles;
  for (const size_t n : {size_t(0), size_t(1), size_t(1023), size_t(1024), size_t(1025), size_t(20000)}) {
    for (const uint32_t slots : {1u, 7u, 1000u}) {
      const std::string what = "items " + std::to_string(n) + ", slots " + std::to_string(slots);
      const auto counts = random_counts(n, uint32_t(n) * 7 + slots);
      const uint64_t total = expect_scan(tiles, counts, what);
      const Keys keys = client_keys(counts, slots, uint32_t(n) + slots);
      ASSERT_EQ(keys.slots.size(), total);
      if (total > 0) {
        tiles.keys().upload(keys.slots.data(), total * 4);
        tiles.values().upload(keys.items.data(), total * 4);
      }
      tiles.sort_and_find_ranges(uint32_t(total), slots);
      expect_sorted(tiles, expected_sort(keys, slots), slots, what);
    }
  }
}

// A consumer of the work list: one group a listed slot (dispatch_work), each counting its visit.
constexpr const char* kVisitSource = R"(
layout(local_size_x = 1) in;
layout(std430, binding = 13) readonly buffer Work { uint work[]; };
layout(std430, binding = 10) readonly buffer State { uint keys; uint work_count; };
layout(std430, binding = 0) buffer Visits { uint visits[]; };
void main() {
  uint group = gl_WorkGroupID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x;
  if (group < work_count) atomicAdd(visits[work[group]], 1u);
}
)";

TEST(GlTileKeys, DispatchesOneGroupPerNonEmptySlotPast65535) {
  // 100000 slots, every other one with keys: 50000 listed; 150000 with keys: past one row of groups.
  static_assert(kTileWorkBinding == 13 && kTileStateBinding == 10, "kVisitSource's bindings");
  HeadlessContext context;
  GlTileKeys tiles;
  Program visit("tile keys test: visit the work list", {{GL_COMPUTE_SHADER, kVisitSource}}, {},
                {tile_work(Access::read), tile_state(Access::read), storage_buffer("visits", 0, Access::read_write)});
  for (const uint32_t slots : {100000u, 150000u}) {
    const uint32_t step = slots == 100000u ? 2u : 1u;
    std::vector<uint32_t> counts(slots / step, 2u);
    const uint64_t total = expect_scan(tiles, counts, "slots " + std::to_string(slots));
    Keys keys;
    for (uint32_t item = 0; item < counts.size(); ++item)
      for (int k = 0; k < 2; ++k) keys.slots.push_back(item * step), keys.items.push_back(item);
    tiles.keys().upload(keys.slots.data(), total * 4);
    tiles.values().upload(keys.items.data(), total * 4);
    tiles.sort_and_find_ranges(uint32_t(total), slots);
    expect_sorted(tiles, expected_sort(keys, slots), slots, "slots " + std::to_string(slots));

    std::vector<uint32_t> none(slots, 0u);
    Buffer visits(size_t(slots) * 4, none.data());
    visit.use();
    tiles.bind(visit);
    visit.bind("visits", visits);
    tiles.dispatch_work(visit);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const auto got = visits.download_as<uint32_t>(slots);
    for (uint32_t s = 0; s < slots; ++s)
      ASSERT_EQ(got[s], s % step == 0 ? 1u : 0u) << "slot " << s << " of " << slots;
  }
}

// The capacity path: keys below the capacity written, the rest left out; the sort keeps the
// written ones (in scan order, stably by slot), the ranges cover min(total, capacity) keys and
// the total on the GPU is the whole one.
TEST(GlTileKeys, MoreKeysThanTheCapacityLeavesKeysOutAndReportsTheTotal) {
  HeadlessContext context;
  GlTileKeys tiles;
  const uint32_t slots = 300;
  for (const size_t n : {size_t(0), size_t(1), size_t(1025), size_t(5000)}) {
    const auto counts = random_counts(n, uint32_t(n) + 11);
    uint64_t total = 0;
    const auto first = exclusive_scan(counts, total);
    const Keys keys = client_keys(counts, slots, uint32_t(n) + 5);
    for (const uint64_t capacity : {total / 2, total, total + 1000}) {
      const std::string what = "items " + std::to_string(n) + ", capacity " + std::to_string(capacity) + " of " +
                               std::to_string(total) + " keys";
      upload_counts(tiles, counts);
      tiles.scan_to_capacity(uint32_t(n), uint32_t(capacity));
      EXPECT_EQ(tiles.capacity(), capacity) << what;
      ASSERT_GE(tiles.keys().bytes(), capacity * 4) << what;
      if (n > 0) {
        const auto got = tiles.counts(n).download_as<uint32_t>(n);
        ASSERT_EQ(got, first) << what << ": the first keys";
      }
      // The client writes only the keys below the capacity (tile_key_writer.glsl's
      // TILE_KEY_CAPACITY); those past it stay 0xFFFFFFFF.
      const size_t written = std::min<uint64_t>(total, capacity);
      if (written > 0) {
        tiles.keys().upload(keys.slots.data(), written * 4);
        tiles.values().upload(keys.items.data(), written * 4);
      }
      if (capacity > written) {
        const auto rest = tiles.keys().download_as<uint32_t>(capacity);
        for (size_t i = written; i < capacity; ++i) ASSERT_EQ(rest[i], kNoKey) << what << ": unwritten key " << i;
      }
      tiles.sort_and_find_ranges_to_capacity(slots);
      Buffer reported(8);
      const uint32_t marker[2] = {0xABCDu, 0xABCDu};
      reported.upload(marker, 8);
      tiles.copy_key_total(reported, 1);
      const auto words = reported.download_as<uint32_t>(2);
      EXPECT_EQ(words[0], 0xABCDu) << what << ": only the word asked for is written";
      EXPECT_EQ(words[1], total) << what << ": the whole total, for the client to grow to";
      Keys kept;
      kept.slots.assign(keys.slots.begin(), keys.slots.begin() + ptrdiff_t(written));
      kept.items.assign(keys.items.begin(), keys.items.begin() + ptrdiff_t(written));
      expect_sorted(tiles, expected_sort(kept, slots), slots, what);
      if (capacity > 0) {
        const uint32_t sorted = tiles.sorter().kept_count_buffer().download_as<uint32_t>(1)[0];
        EXPECT_EQ(sorted, written) << what << ": the sort kept the written keys only";
      }
    }
  }
}

// The tile rasterizers' recovery (gpu/compute/gl_key_capacity.hpp): a capacity kept from pass to
// pass, each pass's total copied on the GPU into its word (the words kept as the buffer grows),
// one read that names the passes over the capacity and grows it past the largest total.
TEST(GlKeyCapacity, ReadsEveryPassTotalOnceAndGrowsPastTheLargest) {
  HeadlessContext context;
  GlTileKeys tiles;
  GlKeyCapacity capacity;
  EXPECT_EQ(capacity.for_pass(100), 100u) << "at first a key an item";
  EXPECT_EQ(capacity.for_pass(5), 100u) << "then kept";
  for (uint32_t pass = 0; pass < 6; ++pass) {  // 0, 30, .. 150 keys
    upload_counts(tiles, std::vector<uint32_t>(30 * pass, 1u));
    tiles.scan_to_capacity(30 * pass, capacity.keys());
    capacity.record(tiles, pass);
  }
  const GlKeyCapacity::FrameKeys frame = capacity.read_frame(6);
  EXPECT_EQ(frame.totals, (std::vector<uint32_t>{0, 30, 60, 90, 120, 150}));
  EXPECT_EQ(frame.sum, 450u);
  EXPECT_EQ(frame.overflowed, (std::vector<uint32_t>{4, 5}));
  EXPECT_EQ(capacity.keys(), 150u + 150u / 4 + 1024u) << "a quarter over the largest, and some";
  // Nothing over: the capacity stays; a largest bound caps the growth.
  EXPECT_TRUE(capacity.read_frame(4).overflowed.empty());
  EXPECT_EQ(capacity.keys(), 1211u);
  capacity.set_keys(10);
  EXPECT_EQ(capacity.read_frame(6, 100).overflowed, (std::vector<uint32_t>{1, 2, 3, 4, 5}));
  EXPECT_EQ(capacity.keys(), 100u);
}

}  // namespace
}  // namespace lfd::gpu
