// Bad input to `lfd calibrate` (docs/calibration.md section 2): every case is an InputError that
// names the file and says what to change, or a warning; nothing is estimated from bad captures.
#include <unistd.h>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "calib/calibrate.hpp"
#include "sim/synthetic_unit.hpp"
#include "display/visual_json.hpp"
#include "tests/calib/cached_captures.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"

namespace lfd::calib {
namespace {

// One simulated position of the Portrait at a small capture size, shared by the cases (and, on
// disk, by their processes).
struct Fixture {
  sim::SyntheticUnit unit;
  sim::PatternSet set;
  sim::CaptureRig rig;
  std::vector<sim::PositionCaptures> captures;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    x.unit = sim::make_synthetic_unit(
        display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json")));
    x.set = sim::plan_patterns(x.unit.nominal);
    x.rig = sim::make_capture_rig(x.unit.truth.display, 480, 1, false, 7);
    // The same pixels in every test process of this build (tests/calib/cached_captures.hpp).
    x.captures = test::cached_captures("bad-input-portrait-480",
                                       [&x] { return sim::simulate_captures(x.set, x.unit.truth, x.rig); });
    return x;
  }();
  return f;
}

CalibrateOptions with_camera() {
  CalibrateOptions o;
  o.camera = fixture().rig.intrinsics;
  return o;
}

// Expects InputError whose message contains every fragment.
template <typename F>
void expect_input_error(F&& f, std::initializer_list<const char*> fragments) {
  try {
    f();
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    for (const char* s : fragments)
      EXPECT_NE(std::string(e.what()).find(s), std::string::npos) << e.what();
  }
}

std::string phase_stem(int k) {
  return (3 + k < 10 ? "0" : "") + std::to_string(3 + k) + "_phase_" + std::to_string(k) + "of8";
}

// The fixture's captures with their own pixels (cv::Mat copies share them).
std::vector<sim::PositionCaptures> copy_captures() {
  auto out = fixture().captures;
  for (auto& pc : out)
    for (auto& [stem, img] : pc.images) img = img.clone();
  return out;
}

TEST(CalibrateBadInput, GoodCapturesOfOnePositionCalibrate) {
  const auto out = calibrate_display(fixture().set, fixture().captures, with_camera());
  EXPECT_FALSE(out.calibration.correction.empty());
  EXPECT_FALSE(out.warnings.empty());  // one position: the view cone is not measured
  EXPECT_FALSE(out.calibration.view_cone_measured_deg.has_value());
  // ...and is refused: the pitch absorbs the cone's error there.
  bool cone_gate = false;
  for (const auto& f : out.gate_failures)
    cone_gate |= f.find("view cone was neither measured nor known") != std::string::npos;
  EXPECT_TRUE(cone_gate);
}

TEST(CalibrateBadInput, OnePositionWithAGivenConeKeepsItAndPassesTheConeGate) {
  CalibrateOptions o = with_camera();
  o.view_cone_deg = fixture().unit.truth.display.view_cone_deg;
  const auto out = calibrate_display(fixture().set, fixture().captures, o);
  ASSERT_TRUE(out.calibration.view_cone_measured_deg.has_value());
  EXPECT_EQ(*out.calibration.view_cone_measured_deg, *o.view_cone_deg);
  EXPECT_EQ(out.calibration.display.view_cone_deg, *o.view_cone_deg);
  for (const auto& f : out.gate_failures) EXPECT_EQ(f.find("view cone"), std::string::npos) << f;
}

TEST(CalibrateBadInput, WrongPatternInAFileIsNamed) {
  auto captures = copy_captures();
  captures[0].images[phase_stem(0)] = captures[0].images.at(phase_stem(4)).clone();
  expect_input_error([&] { calibrate_display(fixture().set, captures, with_camera()); },
                     {phase_stem(0).c_str(), "shows pattern", "07_phase_4of8"});
}

TEST(CalibrateBadInput, MovingCameraIsDetected) {
  auto captures = copy_captures();
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, 12, 0, 1, 5);
  for (int k = 2; k < 8; ++k) {
    cv::Mat& img = captures[0].images.at(phase_stem(k));
    cv::warpAffine(img.clone(), img, shift, img.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  }
  expect_input_error([&] { calibrate_display(fixture().set, captures, with_camera()); },
                     {"camera moved", "tripod"});
}

TEST(CalibrateBadInput, OverExposedCaptureIsNamed) {
  auto captures = copy_captures();
  for (auto& [stem, img] : captures[0].images)
    if (stem != "00_board") cv::min(img * 3.0, 1.0, img);
  expect_input_error([&] { calibrate_display(fixture().set, captures, with_camera()); },
                     {"01_white", "over-exposed"});
}

TEST(CalibrateBadInput, UnderExposedCaptureIsNamed) {
  auto captures = copy_captures();
  for (auto& [stem, img] : captures[0].images)
    if (stem != "00_board") img = img * 0.04;
  expect_input_error([&] { calibrate_display(fixture().set, captures, with_camera()); },
                     {"01_white", "under-exposed"});
}

TEST(CalibrateBadInput, ScreenPartlyOutsideThePhotoIsNamed) {
  auto captures = copy_captures();
  const cv::Size size = captures[0].images.begin()->second.size();
  // Shift everything up by 30 % of the height: the top of the screen leaves the photo.
  const cv::Mat shift = (cv::Mat_<double>(2, 3) << 1, 0, 0, 0, 1, -0.3 * size.height);
  for (auto& [stem, img] : captures[0].images)
    cv::warpAffine(img.clone(), img, shift, size, cv::INTER_LINEAR, cv::BORDER_CONSTANT);
  expect_input_error([&] { calibrate_display(fixture().set, captures, with_camera()); },
                     {"00_board", "outside the photo"});
}

TEST(CalibrateBadInput, MissingBoardIsNamed) {
  auto captures = copy_captures();
  captures[0].images["00_board"] = captures[0].images.at("01_white").clone();
  expect_input_error([&] { calibrate_display(fixture().set, captures, with_camera()); },
                     {"00_board", "no registration board"});
}

TEST(CalibrateBadInput, SelfCalibrationNeedsThreePositions) {
  expect_input_error([&] { calibrate_display(fixture().set, fixture().captures, {}); },
                     {"at least 3 positions", "--camera"});
}

TEST(CalibrateBadInput, QualityGatesRejectAndSayWhy) {
  CalibrateOptions o = with_camera();
  o.gates.max_residual_rms_periods = 1e-4;
  o.gates.max_pitch_sigma_rel = 1e-9;
  const auto out = calibrate_display(fixture().set, fixture().captures, o);
  ASSERT_GE(out.gate_failures.size(), 2u);
  expect_input_error([&] { enforce_gates(out); }, {"rejected", "residual", "pitch uncertainty"});
}

// Captures on disk: missing, extra and unreadable files.
class CaptureFolder : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    patterns_ = std::filesystem::temp_directory_path() / ("lfd_calibrate_bad_input_patterns_" + std::to_string(::getpid()));
    std::filesystem::remove_all(patterns_);
    sim::write_pattern_set(patterns_, fixture().set, false);
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(patterns_); }
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("lfd_calibrate_bad_input_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    std::filesystem::copy(patterns_ / "patterns", dir_ / "patterns");
    const auto& pc = fixture().captures[0];
    std::filesystem::create_directories(dir_ / "captures" / "left");
    for (const auto& [stem, img] : pc.images) {
      cv::Mat bgr, out8;
      cv::cvtColor(img, bgr, cv::COLOR_RGB2BGR);
      bgr.convertTo(out8, CV_8U, 255.0);
      cv::imwrite((dir_ / "captures" / "left" / (stem + ".png")).string(), out8);
    }
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  static inline std::filesystem::path patterns_;
  std::filesystem::path dir_;
};

TEST_F(CaptureFolder, CompleteFolderReadsWithoutWarnings) {
  std::vector<std::string> warnings;
  const auto captures = sim::read_captures(dir_, sim::read_pattern_set(dir_), warnings);
  ASSERT_EQ(captures.size(), 1u);
  EXPECT_EQ(captures[0].images.size(), fixture().set.patterns.size());
  EXPECT_TRUE(warnings.empty());
}

TEST_F(CaptureFolder, MissingCaptureIsNamed) {
  std::filesystem::remove(dir_ / "captures" / "left" / "05_phase_2of8.png");
  std::vector<std::string> warnings;
  expect_input_error([&] { sim::read_captures(dir_, sim::read_pattern_set(dir_), warnings); },
                     {"left", "missing capture", "05_phase_2of8.png"});
}

TEST_F(CaptureFolder, ExtraFileIsAWarningNamingIt) {
  std::filesystem::copy_file(dir_ / "captures" / "left" / "01_white.png",
                             dir_ / "captures" / "left" / "IMG_0001.png");
  std::vector<std::string> warnings;
  sim::read_captures(dir_, sim::read_pattern_set(dir_), warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("IMG_0001.png"), std::string::npos);
}

TEST_F(CaptureFolder, UnreadableCaptureIsNamed) {
  std::ofstream(dir_ / "captures" / "left" / "02_black.png") << "not an image";
  std::vector<std::string> warnings;
  expect_input_error([&] { sim::read_captures(dir_, sim::read_pattern_set(dir_), warnings); },
                     {"02_black.png", "not an image"});
}

TEST_F(CaptureFolder, NoCapturesFolderSaysWhereToPutThem) {
  std::filesystem::remove_all(dir_ / "captures");
  std::vector<std::string> warnings;
  expect_input_error([&] { sim::read_captures(dir_, sim::read_pattern_set(dir_), warnings); },
                     {"captures", "<position>"});
}

// The test cache hands back what was simulated, bit for bit, without simulating again.
TEST(CachedCaptures, TheSecondAskReadsTheFirstSimulationBitForBit) {
  int simulated = 0;
  const auto simulate = [&simulated] {
    ++simulated;
    sim::PositionCaptures pc;
    pc.name = "pos1";
    cv::Mat image(7, 5, CV_32FC3);
    cv::randu(image, -1.0f, 2.0f);
    pc.images.emplace("00_white", image);
    pc.paths.emplace("00_white", "pos1/00_white.png");
    return std::vector<sim::PositionCaptures>{pc};
  };
  const std::string name = "cache-test-" + std::to_string(::getpid());
  const auto first = test::cached_captures(name, simulate);
  const auto second = test::cached_captures(name, simulate);
  EXPECT_EQ(simulated, 1);
  ASSERT_EQ(second.size(), 1u);
  EXPECT_EQ(second[0].name, "pos1");
  EXPECT_EQ(second[0].paths, first[0].paths);
  const cv::Mat& a = first[0].images.at("00_white");
  const cv::Mat& b = second[0].images.at("00_white");
  ASSERT_EQ(b.type(), a.type());
  ASSERT_EQ(b.size(), a.size());
  EXPECT_EQ(std::memcmp(a.data, b.data, a.total() * a.elemSize()), 0);
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(LFD_BINARY_DIR) / "test-cache"))
    if (entry.path().filename().string().rfind(name, 0) == 0) std::filesystem::remove(entry.path());
}

}  // namespace
}  // namespace lfd::calib
