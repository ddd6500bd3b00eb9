// Block phase decoding: the phase of K phase-shifted captures, with the steps a transient
// (glare that comes and goes) pushed off the sinusoid left out, and the harmonics of a camera
// response curve kept (they cancel only over all K steps).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "calib/phasors/block_phasors.hpp"

namespace lfd::calib {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// K uniform 8x8 captures of a + b cos(2 pi (t - k/K)) through `response`, plus `bump` added to
// step `bumped` (none if < 0).
template <typename Response>
std::vector<cv::Mat> captures(double t, int K, Response response, int bumped, double bump) {
  std::vector<cv::Mat> out;
  for (int k = 0; k < K; ++k) {
    double value = response(0.45 + 0.35 * std::cos(kTwoPi * (t - double(k) / K)));
    if (k == bumped) value += bump;
    out.emplace_back(8, 8, CV_32FC3, cv::Scalar::all(std::min(value, 0.97)));
  }
  return out;
}

double wrapped_difference(double a, double b) {
  double d = a - b;
  return d - std::round(d);
}

TEST(BlockPhasors, RecoversThePhaseOfACleanSinusoid) {
  for (double t : {0.03, 0.37, 0.81}) {
    const BlockPhasors bp = block_phasors(captures(t, 8, [](double x) { return x; }, -1, 0), 4);
    ASSERT_EQ(bp.blocks, cv::Size(2, 2));
    EXPECT_NEAR(wrapped_difference(bp.phase(1, 1), t), 0.0, 1e-4);
    EXPECT_NEAR(bp.modulation(1, 1, 8), 0.35 / 0.45, 1e-3);
  }
}

TEST(BlockPhasors, KeepsEveryStepOfAGammaCurvedSinusoid) {
  // A camera response bends the sinusoid (harmonics in every step): all steps stay, and the
  // phase is exact because the harmonics below K - 1 cancel.
  auto gamma = [](double x) { return std::pow(x, 1.0 / 2.2); };
  for (double t : {0.11, 0.52, 0.93}) {
    const BlockPhasors bp = block_phasors(captures(t, 8, gamma, -1, 0), 4);
    EXPECT_NEAR(wrapped_difference(bp.phase(0, 0), t), 0.0, 2e-3) << t;
  }
}

TEST(BlockPhasors, LeavesOutAStepThatGlareLitUp) {
  for (int bumped : {0, 3, 6}) {
    const double t = 0.27;
    const auto caps = captures(t, 8, [](double x) { return x; }, bumped, 0.25);
    // What the plain sum of all steps would give: several times the tolerance below.
    double re = 0, im = 0;
    for (int k = 0; k < 8; ++k) {
      const double v = caps[size_t(k)].at<cv::Vec3f>(0, 0)[0];
      re += v * std::cos(kTwoPi * k / 8);
      im += v * std::sin(kTwoPi * k / 8);
    }
    const double plain = std::atan2(im, re) / kTwoPi;
    EXPECT_GT(std::abs(wrapped_difference(plain, t)), 0.004);
    const BlockPhasors bp = block_phasors(caps, 4);
    EXPECT_NEAR(wrapped_difference(bp.phase(0, 0), t), 0.0, 1e-3) << "step " << bumped;
  }
}

}  // namespace
}  // namespace lfd::calib
