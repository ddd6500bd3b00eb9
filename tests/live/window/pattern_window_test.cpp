// The pattern window on a real X server (Xvfb, Mesa llvmpipe GL; run by xvfb-run, see
// CMakeLists.txt): it finds its monitor, covers the whole screen and puts every pattern byte
// on it unchanged.
#include <random>

#include <gtest/gtest.h>

#include "gpu/gl/glfw_session.hpp"
#include "live/pattern_window.hpp"
#include "sim/patterns.hpp"
#include "display/visual_json.hpp"
#include "tests/live/window/live_test_display.hpp"
#include "tests/live/window/x11_screen.hpp"
#include "util/error.hpp"

namespace lfd::live {
namespace {

// Random bytes: any scaling, filtering, flip, channel swap or colour conversion changes some.
Image8 random_pattern(int w, int h) {
  Image8 image(w, h, 3);
  std::mt19937 rng(7);
  for (auto& v : image.pixels) v = uint8_t(rng() & 0xff);
  return image;
}

long differing_bytes(const Image8& a, const Image8& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) return -1;
  long n = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) n += a.pixels[i] != b.pixels[i];
  return n;
}

TEST(PatternWindow, ShowsThePatternByteForByteOnTheWholeScreen) {
  const display::DisplayCalibration d = display::read_visual_json(test::live_test_display());
  const gpu::GlfwSession glfw;
  // Xvfb's monitor is not named LKG...: the resolution finds it.
  PatternWindow window(glfw, glfw.find_display_monitor("LKG", d.screen_w, d.screen_h),
                       d.screen_w, d.screen_h);
  display::Calibration nominal;
  nominal.display = d;
  const sim::PatternSet set = sim::plan_patterns(nominal);
  // A panel nobody described shows lens probes first (`lfd calibrate --live DIR`): gratings on
  // every subpixel, which any filtering or channel swap would wash out.
  const sim::PatternSet probes = sim::plan_undescribed_patterns(d.screen_w, d.screen_h, d.dpi);
  const Image8 phase = sim::render_pattern(set, *set.of_kind(sim::PatternKind::kPhase).at(1));
  const Image8 probe = sim::render_pattern(probes, *probes.of_kind(sim::PatternKind::kProbe).at(4));
  for (const Image8& pattern : {random_pattern(d.screen_w, d.screen_h), phase, probe}) {
    window.show(pattern);
    EXPECT_EQ(differing_bytes(window.read_back(), pattern), 0) << "framebuffer";
    EXPECT_EQ(differing_bytes(test::grab_x11_screen(), pattern), 0) << "X screen";
  }
}

TEST(PatternWindow, FindsItsMonitorByNamePrefix) {
  const gpu::GlfwSession glfw;
  const auto monitors = glfw.monitors();
  ASSERT_FALSE(monitors.empty());
  ASSERT_FALSE(monitors[0].name.empty());
  // A unique name match wins even when the resolution does not fit.
  EXPECT_NE(glfw.find_display_monitor(monitors[0].name.substr(0, 2), 640, 480), nullptr);
}

TEST(PatternWindow, NoMonitorOfTheDisplaysSizeIsAnInputErrorListingTheMonitors) {
  const gpu::GlfwSession glfw;
  const auto monitors = glfw.monitors();
  ASSERT_FALSE(monitors.empty());
  try {
    glfw.find_display_monitor("LKG", 640, 480);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("640x480"), std::string::npos) << message;
    EXPECT_NE(message.find("\"" + monitors[0].name + "\""), std::string::npos) << message;
    EXPECT_NE(message.find(std::to_string(monitors[0].width_px) + "x" +
                           std::to_string(monitors[0].height_px)),
              std::string::npos)
        << message;
  }
}

TEST(PatternWindow, RefusesAPatternOfAnotherSize) {
  const display::DisplayCalibration d = display::read_visual_json(test::live_test_display());
  const gpu::GlfwSession glfw;
  PatternWindow window(glfw, glfw.find_display_monitor("LKG", d.screen_w, d.screen_h),
                       d.screen_w, d.screen_h);
  EXPECT_THROW(window.show(Image8(d.screen_w / 2, d.screen_h, 3)), InputError);
}

}  // namespace
}  // namespace lfd::live
