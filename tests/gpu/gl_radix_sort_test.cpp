// The GPU radix sort against std::stable_sort (gpu/compute/gl_radix_sort.hpp), on llvmpipe.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <cstdint>
#include <numeric>
#include <optional>
#include <string>
#include <random>
#include <vector>

#include "gpu/gl/gl_context.hpp"
#include "gpu/compute/gl_radix_sort.hpp"

namespace lfd::gpu {
namespace {

struct Sorted {
  std::vector<uint32_t> keys, values;
};

// std::stable_sort of (key, index) pairs by the key's low `key_bits` bits.
Sorted expected_sort(const std::vector<uint32_t>& keys, int key_bits = 32) {
  const uint32_t mask = key_bits == 32 ? 0xFFFFFFFFu : ((1u << key_bits) - 1u);
  std::vector<uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return (keys[a] & mask) < (keys[b] & mask); });
  Sorted s;
  for (uint32_t i : order) {
    s.keys.push_back(keys[i]);
    s.values.push_back(i);
  }
  return s;
}

// Sorts `keys` with values 0..n-1 on the GPU; the buffers hold `slack` more elements, which must
// stay untouched.
Sorted gpu_sort(GlRadixSort& sorter, const std::vector<uint32_t>& keys, int key_bits = 32, size_t slack = 3,
                int low_bit = 0) {
  const size_t n = keys.size();
  std::vector<uint32_t> k = keys, v(n);
  std::iota(v.begin(), v.end(), 0u);
  for (size_t i = 0; i < slack; ++i) {
    k.push_back(0u);
    v.push_back(0xABCD0000u + uint32_t(i));
  }
  Buffer key_buffer(k.size() * 4, k.data()), value_buffer(v.size() * 4, v.data());
  sorter.sort(key_buffer, value_buffer, uint32_t(n), key_bits, low_bit);
  Sorted s;
  s.keys = key_buffer.download_as<uint32_t>(k.size());
  s.values = value_buffer.download_as<uint32_t>(v.size());
  for (size_t i = 0; i < slack; ++i) {
    EXPECT_EQ(s.keys[n + i], 0u) << "past the count";
    EXPECT_EQ(s.values[n + i], 0xABCD0000u + uint32_t(i)) << "past the count";
  }
  s.keys.resize(n);
  s.values.resize(n);
  return s;
}

std::vector<uint32_t> random_keys(size_t n, uint32_t seed, uint32_t modulo = 0) {
  std::mt19937 rng(seed);
  std::vector<uint32_t> keys(n);
  for (auto& k : keys) k = modulo ? rng() % modulo : rng();
  return keys;
}

void expect_same(const Sorted& got, const Sorted& want, const char* what) {
  ASSERT_EQ(got.keys.size(), want.keys.size()) << what;
  for (size_t i = 0; i < want.keys.size(); ++i) {
    ASSERT_EQ(got.keys[i], want.keys[i]) << what << " key at " << i;
    ASSERT_EQ(got.values[i], want.values[i]) << what << " value at " << i << " (not stable?)";
  }
}

TEST(GlRadixSort, SortsAnyCountIncludingEmptyOneAndPartialTiles) {
  HeadlessContext context;
  GlRadixSort sorter;
  for (size_t n : {0, 1, 2, 255, 256, 257, 1000, 4097, 65537}) {
    const auto keys = random_keys(n, uint32_t(n) + 1);
    expect_same(gpu_sort(sorter, keys), expected_sort(keys), "random");
  }
}

TEST(GlRadixSort, IsStableOnDuplicatesAllEqualAndMaximalKeys) {
  HeadlessContext context;
  GlRadixSort sorter;
  const auto few = random_keys(5000, 7, 16);
  expect_same(gpu_sort(sorter, few), expected_sort(few), "16 distinct keys");
  const std::vector<uint32_t> equal(3000, 0x3F800000u);
  expect_same(gpu_sort(sorter, equal), expected_sort(equal), "all equal");
  // Culled splats carry 0xFFFFFFFF and must come after every depth key, in index order.
  auto culled = random_keys(4000, 9);
  for (size_t i = 0; i < culled.size(); i += 3) culled[i] = 0xFFFFFFFFu;
  const Sorted got = gpu_sort(sorter, culled);
  expect_same(got, expected_sort(culled), "with 0xFFFFFFFF");
  EXPECT_EQ(got.keys.back(), 0xFFFFFFFFu);
}

TEST(GlRadixSort, SortsFloatDepthBitsInDepthOrder) {
  HeadlessContext context;
  GlRadixSort sorter;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> depth(0.2f, 1000.0f);
  std::vector<uint32_t> keys(20000);
  std::vector<float> depths(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    depths[i] = depth(rng);
    std::memcpy(&keys[i], &depths[i], 4);
  }
  const Sorted got = gpu_sort(sorter, keys);
  for (size_t i = 1; i < got.values.size(); ++i)
    ASSERT_LE(depths[got.values[i - 1]], depths[got.values[i]]) << i;
}

TEST(GlRadixSort, SortsByTheLowBytesOnlyWithAnOddNumberOfPasses) {
  HeadlessContext context;
  GlRadixSort sorter;
  const auto keys = random_keys(10000, 11);
  const Sorted got = gpu_sort(sorter, keys, 24);
  const Sorted want = expected_sort(keys, 24);
  expect_same(got, want, "24-bit keys");
  const Sorted got8 = gpu_sort(sorter, keys, 8);
  expect_same(got8, expected_sort(keys, 8), "8-bit keys");
}

// The per-view renderer's 24-bit depth keys: the high 24 bits of each key sorted (3 passes),
// keys equal there keeping their input order: std::stable_sort by key >> 8.
TEST(GlRadixSort, SortsByTheHighBitsOnlyStableBelow) {
  HeadlessContext context;
  GlRadixSort sorter;
  for (const size_t n : {size_t(1000), size_t(70000)}) {
    auto keys = random_keys(n, 17, 1u << 20);  // many equal high parts, differing low bytes
    for (auto& k : keys) k = (k << 4) | (k & 0xFu);
    const Sorted got = gpu_sort(sorter, keys, 32, 3, 8);
    std::vector<uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return (keys[a] >> 8) < (keys[b] >> 8); });
    Sorted want;
    for (uint32_t i : order) {
      want.keys.push_back(keys[i]);
      want.values.push_back(i);
    }
    expect_same(got, want, "bits 8..31");
  }
  const Sorted float_bits = gpu_sort(sorter, {0x3F800000u, 0x3F8000FFu, 0x3F800001u, 0x3F7FFFFFu}, 32, 0, 8);
  EXPECT_EQ(float_bits.values, (std::vector<uint32_t>{3, 0, 1, 2}));  // 1.0 and its two neighbours tie
}

TEST(GlRadixSort, SortsBlocksOfSeveralTiles) {
  // Beyond 256 * 1024 keys each work group ranks several tiles in sequence.
  HeadlessContext context;
  GlRadixSort sorter;
  const auto keys = random_keys(300001, 5, 1u << 20);
  expect_same(gpu_sort(sorter, keys), expected_sort(keys), "300001 keys");
}

// Sorting what is visible: the first pass drops the keys 0xFFFFFFFF, stably, and the later
// passes (dispatched indirectly from the kept count the GPU computed) sort the kept ones, which
// end first in std::stable_sort's order; the kept count is on the GPU.
Sorted gpu_sort_kept(GlRadixSort& sorter, const std::vector<uint32_t>& keys, SortKeys how,
                     const std::vector<uint32_t>& range = {}) {
  const size_t n = keys.size();
  std::vector<uint32_t> k = keys, v(n);
  std::iota(v.begin(), v.end(), 0u);
  if (k.empty()) k.push_back(0u), v.push_back(0u);  // a buffer of 0 bytes cannot be made
  Buffer key_buffer(k.size() * 4, k.data()), value_buffer(v.size() * 4, v.data());
  std::optional<Buffer> range_buffer;
  if (!range.empty()) {
    range_buffer.emplace(range.size() * 4, range.data());
    how.key_range = &*range_buffer;
  }
  how.drop_culled = true;
  sorter.sort(key_buffer, value_buffer, uint32_t(n), how);
  const uint32_t kept = sorter.kept_count_buffer().download_as<uint32_t>(1)[0];
  Sorted s;
  s.keys = key_buffer.download_as<uint32_t>(k.size());
  s.values = value_buffer.download_as<uint32_t>(v.size());
  EXPECT_LE(kept, n);  // 0 after a sort of 0 keys too (the sort before kept more)
  s.keys.resize(std::min<size_t>(kept, n));
  s.values.resize(std::min<size_t>(kept, n));
  return s;
}

// The kept (not 0xFFFFFFFF) keys in std::stable_sort order by `order_key`.
template <typename OrderKey>
Sorted expected_kept(const std::vector<uint32_t>& keys, OrderKey order_key) {
  std::vector<uint32_t> order;
  for (uint32_t i = 0; i < keys.size(); ++i)
    if (keys[i] != 0xFFFFFFFFu) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return order_key(keys[a]) < order_key(keys[b]); });
  Sorted s;
  for (uint32_t i : order) {
    s.keys.push_back(keys[i]);
    s.values.push_back(i);
  }
  return s;
}

TEST(GlRadixSort, DropsCulledKeysInTheFirstPassAndSortsTheRestStably) {
  HeadlessContext context;
  GlRadixSort sorter;
  for (const size_t n : {size_t(1000), size_t(0), size_t(1), size_t(2), size_t(255), size_t(70000), size_t(300001)}) {
    for (const double culled : {0.0, 0.3, 1.0}) {
      std::vector<uint32_t> keys = random_keys(n, 23, 1u << 12);  // many ties: stability shows
      std::mt19937 rng(uint32_t(n) + 7);
      for (auto& k : keys)
        if (std::uniform_real_distribution<double>(0, 1)(rng) < culled) k = 0xFFFFFFFFu;
      const auto what = "n " + std::to_string(n) + ", culled " + std::to_string(culled);
      for (const int bits : {32, 24, 8}) {  // 4, 3 (odd: a copy back) and 1 passes
        SortKeys how;
        how.low_bit = 32 - bits;
        const Sorted got = gpu_sort_kept(sorter, keys, how);
        const Sorted want = expected_kept(keys, [&](uint32_t k) { return k >> (32 - bits); });
        expect_same(got, want, (what + ", bits " + std::to_string(bits)).c_str());
      }
    }
  }
}

// A sort's result depends only on its input: not on the sorts run before it with the same
// sorter (their counts, key widths, kept counts, an empty sort between). zink over lavapipe
// (Mesa 22.3) fails this sequence at the one key (its histogram counts nothing; docs/gpu.md
// "What zink found"); llvmpipe passes.
TEST(GlRadixSort, AnEarlierSortLeavesNoTrace) {
  HeadlessContext context;
  GlRadixSort sorter;
  const auto sort_and_check = [&](size_t n, double culled, int bits) {
    std::vector<uint32_t> keys = random_keys(n, 23, 1u << 12);
    std::mt19937 rng(uint32_t(n) + 7);
    for (auto& k : keys)
      if (std::uniform_real_distribution<double>(0, 1)(rng) < culled) k = 0xFFFFFFFFu;
    SortKeys how;
    how.low_bit = 32 - bits;
    const auto what = "n " + std::to_string(n) + ", culled " + std::to_string(culled) + ", bits " + std::to_string(bits);
    expect_same(gpu_sort_kept(sorter, keys, how), expected_kept(keys, [&](uint32_t k) { return k >> (32 - bits); }),
                what.c_str());
  };
  sort_and_check(1000, 1.0, 24);  // three passes, nothing kept
  sort_and_check(1000, 1.0, 8);   // one pass, nothing kept
  sort_and_check(0, 0.0, 32);     // an empty sort
  sort_and_check(1, 0.0, 32);     // one key, four passes
  sort_and_check(1, 0.0, 32);
}

// Normalised keys: (key - min) >> s with s the smallest shift that fits max - min in the bits;
// the first pass writes them, so the kept keys come back normalised, in that order.
TEST(GlRadixSort, NormalisesKeysToTheKeptRange) {
  HeadlessContext context;
  GlRadixSort sorter;
  std::mt19937 rng(5);
  std::vector<uint32_t> keys;
  for (int i = 0; i < 50000; ++i) {
    const float depth = std::uniform_real_distribution<float>(0.5f, 40.0f)(rng);
    uint32_t bits = 0;
    std::memcpy(&bits, &depth, 4);
    keys.push_back(i % 7 == 3 ? 0xFFFFFFFFu : bits);
  }
  keys[10] = keys[20];  // an exact tie
  uint32_t lo = 0xFFFFFFFFu, hi = 0;
  for (uint32_t k : keys)
    if (k != 0xFFFFFFFFu) lo = std::min(lo, k), hi = std::max(hi, k);
  for (const int bits : {8, 16, 24}) {
    int shift = 0;
    while (((hi - lo) >> shift) >= (1u << bits)) ++shift;
    SortKeys how;
    how.normalise_bits = bits;
    const Sorted got = gpu_sort_kept(sorter, keys, how, {lo, hi});
    Sorted want = expected_kept(keys, [&](uint32_t k) { return (k - lo) >> shift; });
    for (auto& k : want.keys) k = (k - lo) >> shift;
    expect_same(got, want, ("normalised to " + std::to_string(bits) + " bits").c_str());
    EXPECT_EQ(got.keys.back() >> (bits - 1), 1u) << "the range fills the top bit";
  }
  SortKeys no_range;
  no_range.normalise_bits = 16;
  Buffer k(16), v(16);
  EXPECT_THROW(sorter.sort(k, v, 4, no_range), std::invalid_argument);
}

}  // namespace
}  // namespace lfd::gpu
