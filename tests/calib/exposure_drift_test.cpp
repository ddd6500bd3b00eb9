// Exposure that drifts between the photos of a phase series: measured on the blocks that show
// no fringe, divided out before the phase is taken.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "util/error.hpp"

#include "calib/phasors/block_phasors.hpp"
#include "sim/camera_effects.hpp"
#include "calib/phasors/exposure_drift.hpp"

namespace lfd::calib {
namespace {

constexpr int kSteps = 8, kWidth = 160, kHeight = 240, kBlock = 4, kRoomCols = 40;

// The true phase of a column of the screen part: under one cycle across, as a phase pattern's
// view fraction is (so the fringe does not average out over the screen).
double true_phase(int x) { return 0.1 + 0.6 * (x - kRoomCols) / double(kWidth - kRoomCols); }

// Rolling-shutter banding of photo k: gain 1 + amplitude sin(2 pi (bands y / height + phi_k)).
struct Banding {
  double amplitude = 0, bands = 2.5;
  double gain(int k, int y) const {
    const double phi = 0.37 * k * k + 0.11 * k;  // a phase of its own in every photo
    return 1 + amplitude * std::sin(2 * std::numbers::pi * (bands * y / kHeight + phi));
  }
};

enum class Room { kEveryRow, kTopHalf, kNone };

// Step k of a series, the photo taken with gain[k] (times the banding along the rows) and
// offset[k]: a room strip without fringes (a dark wall, a white card beside it), then the
// screen, a = 0.45, b = 0.3.
std::vector<cv::Mat> series(const std::vector<double>& gain, const std::vector<double>& offset,
                            Room room = Room::kEveryRow, Banding banding = {}) {
  std::vector<cv::Mat> out;
  for (int k = 0; k < kSteps; ++k) {
    cv::Mat img(kHeight, kWidth, CV_32FC3);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        const bool in_room = x < kRoomCols && (room == Room::kEveryRow ||
                                               (room == Room::kTopHalf && y < kHeight / 2));
        double v = 0;
        if (in_room) v = x < kRoomCols / 2 ? 0.05 : 0.7;
        else v = 0.45 + 0.3 * std::cos(2 * std::numbers::pi * (true_phase(x) - double(k) / kSteps));
        const double g = gain[size_t(k)] * banding.gain(k, y);
        img.at<cv::Vec3f>(y, x) = cv::Vec3f::all(float(g * v + offset[size_t(k)]));
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
  const BlockPhasors p = block_phasors(series(kGain, kOffset, Room::kNone), kBlock);
  EXPECT_TRUE(estimate_exposure_drift(p).photos.empty());
}

// Banding along the rows (a rolling shutter under a flickering light, +-8 %, 2.5 bands):
// one gain per photo leaves it in the phase; the gain fitted along the rows takes it out.
const Banding kFlicker{0.08, 2.5};

TEST(ExposureDrift, BandingAlongTheRowsIsFittedAndDividedOut) {
  const auto photos = series(kGain, kOffset, Room::kEveryRow, kFlicker);
  BlockPhasors fitted = block_phasors(photos, kBlock);
  const ExposureDrift d = estimate_exposure_drift(fitted);
  ASSERT_EQ(d.photos.size(), size_t(kSteps));
  EXPECT_GT(d.row_segments, 0);
  EXPECT_NEAR(d.max_row_variation(), 0.09, 0.03);  // against the mean photo, banded too
  remove_exposure_drift(fitted, d);
  EXPECT_LT(worst_phase_error(fitted), 2e-4);  // measured 4e-5

  BlockPhasors one_gain = block_phasors(photos, kBlock);
  ExposureDriftOptions constant;
  constant.row_segments = 0;
  const ExposureDrift c = estimate_exposure_drift(one_gain, constant);
  ASSERT_EQ(c.photos.size(), size_t(kSteps));
  EXPECT_EQ(c.row_segments, 0);
  remove_exposure_drift(one_gain, c);
  EXPECT_GT(worst_phase_error(one_gain), 1e-2);  // measured 0.03
}

TEST(ExposureDrift, WithoutBandingTheRowFitChangesNothing) {
  const auto photos = series(kGain, kOffset);
  BlockPhasors rows = block_phasors(photos, kBlock), one_gain = rows;
  const ExposureDrift d = estimate_exposure_drift(rows);
  EXPECT_GT(d.row_segments, 0);
  EXPECT_LT(d.max_row_variation(), 1e-3);
  ExposureDriftOptions constant;
  constant.row_segments = 0;
  remove_exposure_drift(rows, d);
  remove_exposure_drift(one_gain, estimate_exposure_drift(one_gain, constant));
  for (int by = 0; by < rows.blocks.height; ++by)
    for (int bx = kRoomCols / kBlock; bx < rows.blocks.width; ++bx) {
      double e = rows.phase(bx, by) - one_gain.phase(bx, by);
      EXPECT_LT(std::abs(e - std::round(e)), 1e-4) << bx << "," << by;
    }
}

// References in the top half only: the lower rows' gain cannot be measured, so one gain per
// photo, said in row_segments.
TEST(ExposureDrift, RowsWithoutReferencesFallBackToOneGainPerPhoto) {
  const BlockPhasors p = block_phasors(series(kGain, kOffset, Room::kTopHalf, kFlicker), kBlock);
  const ExposureDrift d = estimate_exposure_drift(p);
  ASSERT_EQ(d.photos.size(), size_t(kSteps));
  EXPECT_EQ(d.row_segments, 0);
  EXPECT_TRUE(d.photos[0].row_gain.empty());
}

// The simulator's side: each photo (seed) gets its own gain, scaling all its light.
TEST(ExposureDrift, SimulatedPhotosOfOneSceneDifferInGainBySeed) {
  const sim::CameraIntrinsics camera = sim::CameraIntrinsics::from_fov(60, 64, 48);
  auto photo_mean = [&](double drift, uint64_t seed) {
    ImageF image(64, 48, 3, 0.25f);
    sim::CaptureEffects e;
    e.exposure_drift = drift;
    e.seed = seed;
    sim::apply_camera_effects(image, camera, e);
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
  sim::CaptureEffects bad;
  bad.exposure_drift = 0.5;
  EXPECT_THROW(sim::check_effects(bad), InputError);
}

// The simulator's banding: rows brighter and darker by the amplitude, with a phase that
// changes from photo to photo.
TEST(ExposureDrift, SimulatedFlickerBandsTheRowsWithAPhasePerPhoto) {
  const sim::CameraIntrinsics camera = sim::CameraIntrinsics::from_fov(60, 64, 48);
  auto row_means = [&](uint64_t seed) {
    ImageF image(64, 48, 3, 0.4f);
    sim::CaptureEffects e;
    e.flicker_amplitude = 0.1;
    e.flicker_bands = 2;
    e.seed = seed;
    sim::apply_camera_effects(image, camera, e);
    std::vector<double> means;
    for (int y = 0; y < image.height; ++y) {
      double sum = 0;
      for (int i = 0; i < image.width * 3; ++i) sum += image.row(y)[i];
      means.push_back(sum / (image.width * 3));
    }
    return means;
  };
  const auto a = row_means(1), b = row_means(2);
  const auto [lo, hi] = std::ranges::minmax_element(a);
  EXPECT_NEAR(*hi / *lo, 1.1 / 0.9, 0.03);
  double differ = 0;
  for (size_t y = 0; y < a.size(); ++y) differ = std::max(differ, std::abs(a[y] - b[y]));
  EXPECT_GT(differ, 0.01);
  for (auto [amplitude, bands] : {std::pair{0.3, 2.0}, {-0.01, 2.0}, {0.05, 0.0},
                                  {0.05, std::nan("")}}) {
    sim::CaptureEffects bad;
    bad.flicker_amplitude = amplitude;
    bad.flicker_bands = bands;
    EXPECT_THROW(sim::check_effects(bad), InputError) << amplitude << " " << bands;
  }
}

}  // namespace
}  // namespace lfd::calib
