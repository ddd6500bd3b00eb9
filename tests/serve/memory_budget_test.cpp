// The memory budget and the quilts decoded once per content (serve/memory_budget.hpp,
// serve/decoded_quilts.hpp).
#include <gtest/gtest.h>

#include <vector>

#include "serve/decoded_quilts.hpp"
#include "serve/memory_budget.hpp"
#include "tests/serve/serve_test_support.hpp"
#include "util/error.hpp"

namespace lfd::serve {
namespace {

TEST(MemoryBudget, ReservationsCountUntilReleasedAndRefuseOverTheLimit) {
  MemoryBudget budget(100);
  auto a = budget.try_reserve(60);
  ASSERT_TRUE(a);
  EXPECT_EQ(budget.used(), 60u);
  EXPECT_FALSE(budget.try_reserve(41));  // 101 > 100
  EXPECT_THROW(budget.reserve_or_busy(41, "a quilt"), BusyError);
  EXPECT_THROW(budget.reserve_or_busy(101, "a quilt"), InputError);  // never fits: not busy
  auto moved = std::move(a);
  EXPECT_EQ(budget.used(), 60u);
  moved.release();
  EXPECT_EQ(budget.used(), 0u);
  EXPECT_TRUE(budget.try_reserve(100));
  EXPECT_EQ(budget.used(), 0u);  // the temporary released it again
  EXPECT_EQ(budget.refused(), 2u);  // the one that never fits is bad input, not a refusal for room
}

TEST(DecodedQuilts, TheSameBytesAreDecodedOnceAndCountWhileHeld) {
  test::TempDir tmp;
  const Image8 quilt = test::pattern_quilt(64, 48);
  const auto png = test::png_bytes(quilt, tmp.path);
  ServeLimits limits;
  MemoryBudget budget(1 << 20);
  DecodedQuilts decoded(budget, limits);
  const auto first = decoded.decode(png, "bin");
  const auto again = decoded.decode(png, "bin");
  EXPECT_EQ(decoded.decodes(), 1u);
  EXPECT_EQ(first.get(), again.get());
  EXPECT_EQ(first->pixels, quilt.pixels);
  EXPECT_EQ(budget.used(), quilt.pixels.size());  // the picture, stb's working copy gone
}

TEST(DecodedQuilts, ADecodeTheBudgetCannotTakeNowIsBusyAndOneItNeverCouldIsBadInput) {
  test::TempDir tmp;
  const auto png = test::png_bytes(test::pattern_quilt(256, 256), tmp.path);  // 192 KiB as RGB
  ServeLimits limits;
  MemoryBudget budget(500 * 1024);
  DecodedQuilts decoded(budget, limits);
  {
    const auto other = budget.try_reserve(200 * 1024);  // another request's content
    EXPECT_THROW(decoded.decode(png, "bin"), BusyError);  // the picture and stb's copy: 384 KiB
    EXPECT_EQ(budget.used(), 200u * 1024);
  }
  budget.set_aside(200 * 1024, "the service itself");
  EXPECT_THROW(decoded.decode(png, "bin"), InputError);  // 384 KiB > the 300 KiB left for requests
  EXPECT_EQ(decoded.decodes(), 0u);
  EXPECT_EQ(budget.used(), 0u);
}

TEST(MemoryBudget, APartSplitOffCountsUntilItGoes) {
  MemoryBudget budget(100);
  auto job = budget.try_reserve(80);
  auto result = job.split(30);
  EXPECT_EQ(job.bytes(), 50u);
  EXPECT_EQ(result.bytes(), 30u);
  job.release();
  EXPECT_EQ(budget.used(), 30u);
  result.release();
  EXPECT_EQ(budget.used(), 0u);
}

TEST(MemoryBudget, ContentIsRefusedWhileTheProcessHoldsTheWholeBudget) {
  constexpr std::size_t kMiB = 1u << 20;
  MemoryBudget budget(std::size_t{1} << 40);  // the count alone would take anything
  budget.limit_resident(resident_bytes() + 64 * kMiB);
  EXPECT_FALSE(budget.try_reserve(128 * kMiB));  // more than the process may still add
  EXPECT_THROW(budget.reserve_or_busy(128 * kMiB, "a quilt"), BusyError);
  EXPECT_TRUE(budget.try_reserve(4 * kMiB));
  // What the count cannot see (here a buffer of the test's own, as NNG's reception would be)
  // fills the process: content is refused, small messages still pass.
  std::vector<char> unseen(96 * kMiB, 1);
  EXPECT_FALSE(budget.try_reserve(4 * kMiB));
  EXPECT_TRUE(budget.try_reserve(MemoryBudget::kResidentCheckFrom - 1));
  unseen = {};
  unseen.shrink_to_fit();
  EXPECT_TRUE(budget.try_reserve(4 * kMiB));  // freed: admitted again
}

}  // namespace
}  // namespace lfd::serve
