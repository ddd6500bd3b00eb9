// Exposure that drifts between the photos of a phase series: measured on the blocks that show
// no fringe, divided out before the phase is taken.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "util/error.hpp"

#include "calib/block_phasors.hpp"
#include "calib/camera_effects.hpp"
#include "calib/exposure_drift.hpp"

namespace lfd::calib {
namespace {

constexpr int kSteps = 8, kWidth = 160, kHeight = 120, kBlock = 4, kRoomCols = 40;

// The true phase of a column of the screen part: under one cycle across, as a phase pattern's
// view fraction is (so the fringe does not average out over the screen).
double true_phase(int x) { return 0.1 + 0.6 * (x - kRoomCols) / double(kWidth - kRoomCols); }

// Step k of a series, the photo taken with gain[k] and offset[k]: a room strip (dark above, a
// white card below) without fringes, then the screen, a = 0.45, b = 0.3.
std::vector<cv::Mat> series(const std::vector<double>& gain, const std::vector<double>& offset,
                            bool with_room = true) {
  std::vector<cv::Mat> out;
  for (int k = 0; k < kSteps; ++k) {
    cv::Mat img(kHeight, kWidth, CV_32FC3);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        double v = 0;
        if (x < kRoomCols && with_room) v = y < kHeight / 2 ? 0.05 : 0.7;
        else v = 0.45 + 0.3 * std::cos(2 * std::numbers::pi * (true_phase(x) - double(k) / kSteps));
        img.at<cv::Vec3f>(y, x) = cv::Vec3f::all(float(gain[size_t(k)] * v + offset[size_t(k)]));
      }
    out.push_back(img);
  }
  return out;
}

// The largest phase error over the screen's blocks.
double worst_phase_error(const BlockPhasors& p) {
  double worst = 0;
  for (int by = 0; by < p.blocks.height; ++by)
    for (int bx = kRoomCols / kBlock; bx < p.blocks.width; ++bx) {
      const double truth = true_phase(bx * kBlock) +
                           0.6 * (0.5 * kBlock - 0.5) / double(kWidth - kRoomCols);
      double e = p.phase(bx, by) - truth;
      e -= std::round(e);
      worst = std::max(worst, std::abs(e));
    }
  return worst;
}

const std::vector<double> kGain = {1.04, 0.97, 1.05, 0.96, 1.00, 1.03, 0.95, 1.00};
const std::vector<double> kOffset = {0.01, -0.005, 0.0, 0.008, -0.01, 0.0, 0.004, -0.007};

TEST(ExposureDrift, BiasesThePhaseWhenLeftIn) {
  const BlockPhasors p = block_phasors(series(kGain, kOffset), kBlock);
  EXPECT_GT(worst_phase_error(p), 0.002);  // 0.003 periods, most of the 0.005 center bar
}

TEST(ExposureDrift, GainAndOffsetPerPhotoAreMeasuredOnUnmodulatedBlocks) {
  const BlockPhasors p = block_phasors(series(kGain, kOffset), kBlock);
  const ExposureDrift d = estimate_exposure_drift(p);
  ASSERT_EQ(d.photos.size(), size_t(kSteps));
  EXPECT_TRUE(d.offset_fitted);
  EXPECT_GE(d.reference_blocks, (kRoomCols / kBlock) * (kHeight / kBlock) - 2);
  // Relative to the series' mean photo: gain / mean gain.
  double mean_gain = 0;
  for (double g : kGain) mean_gain += g / kSteps;
  for (int k = 0; k < kSteps; ++k)
    EXPECT_NEAR(d.photos[size_t(k)].gain, kGain[size_t(k)] / mean_gain, 1e-3) << k;
}

TEST(ExposureDrift, CorrectedPhaseIsUnbiased) {
  BlockPhasors p = block_phasors(series(kGain, kOffset), kBlock);
  remove_exposure_drift(p, estimate_exposure_drift(p));
  EXPECT_LT(worst_phase_error(p), 2e-4);
}

TEST(ExposureDrift, SteadyExposureIsLeftAlone) {
  const std::vector<double> one(kSteps, 1.0), zero(kSteps, 0.0);
  const ExposureDrift d = estimate_exposure_drift(block_phasors(series(one, zero), kBlock));
  ASSERT_EQ(d.photos.size(), size_t(kSteps));
  EXPECT_LT(d.max_gain_change(), 1e-4);
}

TEST(ExposureDrift, NothingToMeasureWithoutUnmodulatedBlocks) {
  const BlockPhasors p = block_phasors(series(kGain, kOffset, false), kBlock);
  EXPECT_TRUE(estimate_exposure_drift(p).photos.empty());
}

// The simulator's side: each photo (seed) gets its own gain, scaling all its light.
TEST(ExposureDrift, SimulatedPhotosOfOneSceneDifferInGainBySeed) {
  const CameraIntrinsics camera = CameraIntrinsics::from_fov(60, 64, 48);
  auto photo_mean = [&](double drift, uint64_t seed) {
    ImageF image(64, 48, 3, 0.25f);
    CaptureEffects e;
    e.exposure_drift = drift;
    e.seed = seed;
    apply_camera_effects(image, camera, e);
    double sum = 0;
    for (float v : image.pixels) sum += v;
    return sum / double(image.pixels.size());
  };
  EXPECT_EQ(photo_mean(0, 1), photo_mean(0, 2));
  EXPECT_EQ(photo_mean(0.05, 3), photo_mean(0.05, 3));
  double lo = 1, hi = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    lo = std::min(lo, photo_mean(0.05, seed));
    hi = std::max(hi, photo_mean(0.05, seed));
  }
  EXPECT_GT(hi / lo, 1.03);
  CaptureEffects bad;
  bad.exposure_drift = 0.5;
  EXPECT_THROW(check_effects(bad), InputError);
}

}  // namespace
}  // namespace lfd::calib
