// The calibration patterns (docs/calibration.md section 1): layout, pixel values, manifest round
// trip.
#include <unistd.h>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "display/lens_model.hpp"
#include "sim/corner_markers.hpp"
#include "sim/patterns.hpp"
#include "calib/registration/registration.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

display::Calibration portrait() {
  display::Calibration c;
  c.display = display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  return c;
}

cv::Mat gray_quarter(const Image8& img) {
  cv::Mat m(img.height, img.width, CV_8UC3, const_cast<uint8_t*>(img.pixels.data())), g, small;
  cv::cvtColor(m, g, cv::COLOR_RGB2GRAY);
  cv::resize(g, small, cv::Size(), 0.25, 0.25, cv::INTER_AREA);
  return small;
}

TEST(PatternsGeneration, ListsBoardWhiteBlackAndKPhaseSteps) {
  sim::PatternOptions o;
  o.phase_steps = 6;
  const sim::PatternSet set = sim::plan_patterns(portrait(), o);
  EXPECT_EQ(set.patterns.size(), 3u + 6u + 8u);
  EXPECT_EQ(set.of_kind(sim::PatternKind::kBoard).size(), 1u);
  EXPECT_EQ(set.of_kind(sim::PatternKind::kPhase).size(), 6u);
  EXPECT_EQ(set.of_kind(sim::PatternKind::kFringeX).size(), 4u);
  EXPECT_EQ(set.of_kind(sim::PatternKind::kFringeY).size(), 4u);
  o.fringes = false;
  EXPECT_EQ(sim::plan_patterns(portrait(), o).patterns.size(), 3u + 6u);
  EXPECT_NE(set.find("00_board"), nullptr);
  EXPECT_EQ(set.find("nonexistent"), nullptr);
}

TEST(PatternsGeneration, PhasePatternShowsTheNominalViewFractionSinusoid) {
  const sim::PatternSet set = sim::plan_patterns(portrait());
  const sim::PatternInfo& p = *set.of_kind(sim::PatternKind::kPhase).at(3);
  const Image8 img = sim::render_pattern(set, p);
  const display::LensModel lens(set.nominal.display);
  for (auto [x, row] : {std::pair{700, 900}, {800, 1500}, {401, 1203}})
    for (int c = 0; c < 3; ++c) {
      const double f = lens.subpixel_view_fraction(x, row, c);
      const double expected = 0.5 + 0.5 * std::cos(2 * std::numbers::pi * (f - 3.0 / 8));
      EXPECT_NEAR(img.at(x, row, c) / 255.0, expected, 0.5 / 255 + 1e-9);
    }
}

TEST(PatternsGeneration, FringePatternsShowTheSameSinusoidInEveryViewAlongTheirAxis) {
  const sim::PatternSet set = sim::plan_patterns(portrait());
  ASSERT_GE(set.fringe_period_px, 48.0);
  for (sim::PatternKind kind : {sim::PatternKind::kFringeX, sim::PatternKind::kFringeY}) {
    const sim::PatternInfo& p = *set.of_kind(kind).at(1);
    const Image8 img = sim::render_pattern(set, p);
    for (auto [x, row] : {std::pair{700, 900}, {800, 1500}, {401, 1203}}) {
      const double t = (kind == sim::PatternKind::kFringeX ? x : row) / set.fringe_period_px - 0.25;
      const double expected = 0.5 + 0.5 * std::cos(2 * std::numbers::pi * t);
      for (int c = 0; c < 3; ++c)  // all subpixels of a pixel alike: no view dependence
        EXPECT_NEAR(img.at(x, row, c) / 255.0, expected, 0.5 / 255 + 1e-9) << to_string(kind);
    }
  }
}

TEST(PatternsGeneration, BoardCornersInTheManifestAreWhereTheBoardIsDrawn) {
  const sim::PatternSet set = sim::plan_patterns(portrait());
  const Image8 img = sim::render_pattern(set, set.patterns.at(0));
  const BoardDetection b = detect_board(gray_quarter(img), set);
  ASSERT_GT(b.ids.size(), 20u);
  for (size_t i = 0; i < b.ids.size(); ++i) {
    // A quarter-size pixel centre i sits at full-size coordinate 4 i + 1.5.
    const cv::Point2d full(b.image_px[i].x * 4 + 1.5, b.image_px[i].y * 4 + 1.5);
    EXPECT_LT(cv::norm(full - set.board.corners_px.at(size_t(b.ids[i]))), 1.0) << b.ids[i];
  }
}

TEST(PatternsGeneration, CornerMarkersEncodeThePatternIndex) {
  const sim::PatternSet set = sim::plan_patterns(portrait());
  const sim::PatternInfo& p = set.patterns.at(5);
  const auto markers = detect_corner_markers(gray_quarter(sim::render_pattern(set, p)));
  ASSERT_EQ(markers.size(), 4u);
  for (const auto& [id, centre] : markers) {
    EXPECT_EQ(id / 4, p.index);
    const cv::Point2d expected = set.markers.centres_px.at(size_t(id % 4));
    EXPECT_LT(cv::norm(cv::Point2d(centre.x * 4 + 1.5, centre.y * 4 + 1.5) - expected), 3.0);
  }
}

// Registration takes the markers' outer corners as correspondences at the screen's corners
// (sim/corner_markers.hpp): where ArUco finds them in the drawn pattern, in corner order.
TEST(PatternsGeneration, CornerMarkerOuterCornersAreWhereArucoFindsThem) {
  const sim::PatternSet set = sim::plan_patterns(portrait());
  const sim::PatternInfo& p = set.patterns.at(1);
  const auto found = detect_corner_marker_corners(gray_quarter(sim::render_pattern(set, p)));
  ASSERT_EQ(found.size(), 4u);
  for (const auto& [id, corners] : found) {
    const auto expected = sim::marker_outer_corners_px(set.markers, id % 4);
    for (size_t k = 0; k < 4; ++k) {
      // A quarter-size pixel's edge at x sits at full-size 4 x + 1.5 too (both are affine).
      const cv::Point2d full(corners[k].x * 4 + 1.5, corners[k].y * 4 + 1.5);
      EXPECT_LT(cv::norm(full - expected[k]), 2.0) << "marker " << id << " corner " << k << ": "
                                                   << full << " vs " << expected[k];
    }
  }
}

TEST(PatternsGeneration, ManifestRoundTripsAndIsNotOverwrittenWithoutForce) {
  const auto dir = std::filesystem::temp_directory_path() / ("lfd_patterns_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  sim::PatternOptions o;
  o.phase_steps = 3;
  const sim::PatternSet set = sim::plan_patterns(portrait(), o);
  sim::write_pattern_set(dir, set, false);
  for (const auto& p : set.patterns) EXPECT_TRUE(std::filesystem::exists(dir / "patterns" / p.file));
  const sim::PatternSet back = sim::read_pattern_set(dir);
  EXPECT_EQ(back.phase_steps, 3);
  EXPECT_EQ(back.fringe_steps, set.fringe_steps);
  EXPECT_DOUBLE_EQ(back.fringe_period_px, set.fringe_period_px);
  EXPECT_EQ(back.patterns.size(), set.patterns.size());
  for (size_t i = 0; i < set.patterns.size(); ++i) {
    EXPECT_EQ(back.patterns[i].kind, set.patterns[i].kind) << set.patterns[i].file;
    EXPECT_EQ(back.patterns[i].step, set.patterns[i].step) << set.patterns[i].file;
  }
  EXPECT_EQ(back.board.corners_px.size(), set.board.corners_px.size());
  EXPECT_DOUBLE_EQ(back.nominal.display.pitch_lpi, set.nominal.display.pitch_lpi);
  EXPECT_THROW(sim::write_pattern_set(dir, set, false), InputError);
  std::filesystem::remove_all(dir);
}

TEST(PatternsGeneration, ManifestWithoutFringesReadsAsBoardOnlyRegistration) {
  // Pattern folders written before the fringe patterns existed stay usable.
  const auto dir = std::filesystem::temp_directory_path() /
                   ("lfd_patterns_nofringe_test_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  sim::PatternOptions o;
  o.fringes = false;
  sim::write_pattern_set(dir, sim::plan_patterns(portrait(), o), false);
  const sim::PatternSet back = sim::read_pattern_set(dir);
  EXPECT_EQ(back.fringe_steps, 0);
  EXPECT_TRUE(back.of_kind(sim::PatternKind::kFringeX).empty());
  EXPECT_EQ(back.patterns.size(), 3u + 8u);
  std::filesystem::remove_all(dir);
}

TEST(PatternsGeneration, MissingManifestNamesTheFileAndTheCommand) {
  try {
    sim::read_pattern_set("/nonexistent/unit");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("manifest.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("lfd patterns"), std::string::npos);
  }
}

}  // namespace
}  // namespace lfd::calib
