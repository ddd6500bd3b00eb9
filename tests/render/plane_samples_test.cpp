// render::sample_window (render/plane_samples.hpp): the AVX2 kernel against the scalar one, bit
// for bit, on random windows of a random blended row (live, stopped and nearly stopped rays,
// samples inside, at the edges and past the row), and the contract both keep: stopped rays and
// the slots outside the window are left as they were.
#include "render/plane_samples.hpp"

#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace lfd::render {
namespace {

struct Row {
  int length = 0, stride = 0;
  std::vector<float> values;  // R, G, B, T
};

Row random_row(std::mt19937& rng, int length) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Row r;
  r.length = length;
  r.stride = (length + 15) & ~15;
  r.values.assign(4 * size_t(r.stride), 0.0f);
  for (int x = 0; x < length; ++x) {
    const bool empty = x < 2 || x >= length - 2 || unit(rng) < 0.3f;  // padding and gaps
    const float t = empty ? 1.0f : unit(rng);
    for (int c = 0; c < 3; ++c) r.values[size_t(c) * size_t(r.stride) + size_t(x)] = empty ? 0.0f : (1.0f - t) * unit(rng);
    r.values[3 * size_t(r.stride) + size_t(x)] = t;
  }
  return r;
}

// The slot arrays of a row of rays, padded as the kernels may read them.
struct Slots {
  std::vector<float> dx, u, colour, trans;
  std::vector<int32_t> channel_offset;
};

Slots random_slots(std::mt19937& rng, size_t n, int stride) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Slots s;
  const size_t padded = n + kSampleWindowOverread;
  s.dx.assign(padded, 0.0f);
  s.u.assign(padded, 0.0f);
  s.colour.assign(padded, 0.0f);
  s.trans.assign(padded, 0.0f);
  s.channel_offset.assign(padded, 0);
  for (size_t i = 0; i < n; ++i) {
    s.dx[i] = unit(rng) * 2.0f - 1.0f;
    s.u[i] = unit(rng) * 2.4f - 1.2f;  // some samples fall past either end of the row
    s.colour[i] = unit(rng) * 0.5f;
    const float pick = unit(rng);
    // Live, stopped, and just either side of the stopping transmittance.
    s.trans[i] = pick < 0.6f   ? unit(rng)
                 : pick < 0.8f ? unit(rng) * kPlaneRayMinTransmittance
                 : pick < 0.9f ? kPlaneRayMinTransmittance
                               : kPlaneRayMinTransmittance * 1.01f;
    s.channel_offset[i] = int32_t(rng() % 3) * stride;
  }
  return s;
}

SampleWindow window_over(const Row& r, Slots& s, float ax, float au, float a0) {
  return {r.values.data(), r.values.data() + 3 * size_t(r.stride), r.length, ax, au, a0, s.dx.data(), s.u.data(),
          s.channel_offset.data(), s.colour.data(), s.trans.data()};
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(PlaneSamples, VectorKernelEqualsTheScalarOneBitForBit) {
  if (!sample_kernel_available(SampleKernel::kAvx2)) GTEST_SKIP() << "this CPU has no AVX2: the scalar kernel alone runs";
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int windows = 0, fell = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Row row = random_row(rng, 8 + int(rng() % 120));
    const size_t n = 1 + rng() % 70;
    const Slots start = random_slots(rng, n, row.stride);
    const float ax = unit(rng) * 20.0f - 10.0f, au = float(row.length) * 0.5f * (0.5f + unit(rng));
    const float a0 = float(row.length) * 0.5f + unit(rng) * 4.0f - 2.0f;
    const size_t i0 = rng() % n, i1 = i0 + rng() % (n - i0 + 1);
    for (bool bilinear : {true, false}) {
      Slots scalar = start, vector = start;
      const int fell_scalar =
          sample_window(SampleKernel::kScalar, window_over(row, scalar, ax, au, a0), i0, i1, bilinear);
      const int fell_vector =
          sample_window(SampleKernel::kAvx2, window_over(row, vector, ax, au, a0), i0, i1, bilinear);
      EXPECT_EQ(fell_scalar, fell_vector) << "trial " << trial;
      EXPECT_TRUE(same_bits(scalar.colour, vector.colour)) << "trial " << trial;
      EXPECT_TRUE(same_bits(scalar.trans, vector.trans)) << "trial " << trial;
      ++windows;
      fell += fell_scalar;
    }
  }
  EXPECT_EQ(windows, 800);
  EXPECT_GT(fell, 0);  // some rays stopped: the count was exercised
}

TEST(PlaneSamples, StoppedRaysAndSlotsOutsideTheWindowStayAsTheyWere) {
  std::mt19937 rng(9);
  const Row row = random_row(rng, 64);
  for (SampleKernel kernel : {SampleKernel::kScalar, SampleKernel::kAvx2}) {
    if (!sample_kernel_available(kernel)) continue;
    for (bool bilinear : {true, false}) {
      const size_t n = 37;
      Slots s = random_slots(rng, n, row.stride);
      const Slots before = s;
      const size_t i0 = 5, i1 = 29;
      const int fell = sample_window(kernel, window_over(row, s, 3.0f, 30.0f, 32.0f), i0, i1, bilinear);
      int fell_counted = 0;
      for (size_t i = 0; i < s.trans.size(); ++i) {
        const bool inside = i >= i0 && i < i1;
        const bool live = before.trans[i] >= kPlaneRayMinTransmittance;
        if (!inside || !live) {
          EXPECT_EQ(s.trans[i], before.trans[i]) << i;
          EXPECT_EQ(s.colour[i], before.colour[i]) << i;
        } else {
          EXPECT_LE(s.trans[i], before.trans[i]) << i;  // a sample only lets less light through
          EXPECT_GE(s.colour[i], before.colour[i]) << i;
          fell_counted += s.trans[i] < kPlaneRayMinTransmittance;
        }
      }
      EXPECT_EQ(fell, fell_counted);
    }
  }
}

}  // namespace
}  // namespace lfd::render
