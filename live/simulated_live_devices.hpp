#pragma once
// The live loop's devices for `--simulate` and the tests (live/live_devices.hpp): a display
// that only remembers the pattern, and a camera that photographs whatever a screen shows
// through the optics simulator looking at a TRUE unit. The camera takes the screen as a
// function so a test can hand it a real window's read-back framebuffer instead.
#include <functional>

#include "live/live_devices.hpp"
#include "sim/synthetic_unit.hpp"

namespace lfd::live {

class RememberedPattern : public PatternDisplay {
 public:
  void show(const Image8& pattern) override { pattern_ = pattern; }
  const Image8& pattern() const { return pattern_; }

 private:
  Image8 pattern_;
};

class SimulatedCamera : public FrameSource {
 public:
  // `screen` returns the panel image on screen now (screenW x screenH of the truth).
  SimulatedCamera(const display::Calibration& truth, sim::CaptureRig rig, std::function<Image8()> screen);

  // Switches to pose `index` of the rig (positions beyond the rig's poses wrap around).
  void start_position(int index, int count) override;
  // Manual exposure as a user would set it on the white pattern (exposure_on_white).
  void fix_exposure_on_white() override;
  // How often the settings were locked (once per session is right).
  int settings_locks() const { return locks_; }
  // One simulated photograph; its noise seed depends on the position and the photograph's
  // number there, as in simulate_captures.
  cv::Mat capture() override;
  // The next photograph's view, without counting as one (noise seeds stay as without it).
  cv::Mat preview() override;

 private:
  sim::PhysicalCamera camera() const;

  sim::DisplaySimulator simulator_;
  sim::CaptureRig rig_;
  std::function<Image8()> screen_;
  int position_ = 0;
  int photo_ = 0;  // photographs taken at this position
  double exposure_;
  int locks_ = 0;
};

}  // namespace lfd::live
