// `lfd calibrate --live` on a machine without the hardware: each missing device is bad input
// (exit 2) with one line that says which. Runs under xvfb-run (CMakeLists.txt): the virtual
// screen is the display's size, so the monitor is found and the camera is what is missing;
// the no-display case removes DISPLAY for the program it starts.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_lfd.hpp"
#include "tests/live/window/live_test_display.hpp"

namespace {

namespace fs = std::filesystem;

fs::path out_path() {
  return fs::temp_directory_path() /
         ("lfd_calibrate_live_cli_test_" + std::to_string(::getpid()) + ".json");
}

std::string live_args(int camera_index) {
  return "calibrate --live --display " + lfd::test::live_test_display().string() +
         " --positions 3 --camera-index " + std::to_string(camera_index) + " --out " +
         out_path().string();
}

long lines_of(const std::string& text) {
  long n = 0;
  for (char c : text) n += c == '\n';
  return n + (!text.empty() && text.back() != '\n');
}

// Unsets an environment variable for the lifetime of the guard.
class UnsetEnv {
 public:
  explicit UnsetEnv(const char* name) : name_(name) {
    if (const char* v = std::getenv(name)) old_ = v;
    ::unsetenv(name);
  }
  ~UnsetEnv() {
    if (old_) ::setenv(name_, old_->c_str(), 1);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

TEST(CalibrateLiveCli, NoCameraAtTheIndexExitsTwoNamingIt) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run";
  const auto r = lfd::test::run_lfd(live_args(7));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(lines_of(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("no camera at index 7"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out_path()));
}

TEST(CalibrateLiveCli, NoDisplayExitsTwoSayingSo) {
  const UnsetEnv display("DISPLAY"), wayland("WAYLAND_DISPLAY");
  const auto r = lfd::test::run_lfd(live_args(7));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(lines_of(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("no display"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out_path()));
}

TEST(CalibrateLiveCli, WithoutIntrinsicsOnePositionIsRefusedBeforeAnythingOpens) {
  const auto r = lfd::test::run_lfd("calibrate --live --display " +
                                    lfd::test::live_test_display().string() + " --out " +
                                    out_path().string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(lines_of(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--camera"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--positions 3"), std::string::npos) << r.output;
}

TEST(CalibrateLiveCli, OnePositionWithoutAKnownViewConeIsRefusedBeforeAnythingOpens) {
  const fs::path camera = fs::temp_directory_path() /
                          ("lfd_calibrate_live_cli_camera_" + std::to_string(::getpid()) + ".yaml");
  {
    std::ofstream f(camera);
    f << "%YAML:1.0\n---\ncamera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
         "   data: [ 1000., 0., 960., 0., 1000., 540., 0., 0., 1. ]\n"
         "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: 5\n   dt: d\n"
         "   data: [ 0., 0., 0., 0., 0. ]\nimage_width: 1920\nimage_height: 1080\n";
  }
  const auto r = lfd::test::run_lfd("calibrate --live --display " +
                                    lfd::test::live_test_display().string() + " --camera " +
                                    camera.string() + " --out " + out_path().string());
  fs::remove(camera);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(lines_of(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("--view-cone"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out_path()));
}

}  // namespace
