#pragma once
// The display of the tests that need an X server: LKG-PORT-portrait (1536x2048), the unit the
// simulated live test calibrates; tests/live/window/CMakeLists.txt starts Xvfb with a screen
// of exactly this size, so the pattern window finds its monitor by resolution.
#include <filesystem>

namespace lfd::test {

inline std::filesystem::path live_test_display() {
  return std::filesystem::path(LFD_TEST_DATA_DIR) / "calibrations" / "LKG-PORT-portrait.visual.json";
}

}  // namespace lfd::test
