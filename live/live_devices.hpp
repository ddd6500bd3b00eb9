#pragma once
// The two devices the live calibration loop (live/live_calibration.hpp) talks to: something
// that shows a pattern on the display's panel and something that photographs it. The real
// ones are a full-screen GLFW window and a cv::VideoCapture camera (live/); the
// simulated ones remember the pattern and photograph it through the optics simulator
// (live/simulated_live_devices.hpp). The loop does not know which it has.
#include <opencv2/core.hpp>

#include "util/image.hpp"

namespace lfd::live {

class PatternDisplay {
 public:
  virtual ~PatternDisplay() = default;
  // Shows `pattern` (8-bit RGB at the panel's resolution, row 0 = top) pixel for pixel and
  // returns once it is on screen, so the next camera frame sees it.
  virtual void show(const Image8& pattern) = 0;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // The camera now stands at position `index` (0-based) of `count`. A real camera has been
  // moved by the user; a simulated one switches its pose. Settings locked stay locked.
  virtual void start_position(int index, int count) = 0;
  // Called once per session, while the white pattern is on screen before the first
  // photograph: fix exposure (and white balance, focus) for it, then keep them for every
  // position and round (the phase decoding compares brightness pixel by pixel, and the
  // focus must not hunt between photographs).
  virtual void fix_exposure_on_white() = 0;
  // A photograph of what is on screen now, taken after the last show(): CV_32FC3, RGB, values
  // in [0, 1]. Frames buffered before the pattern changed are not used.
  virtual cv::Mat capture() = 0;
  // One frame of what the camera sees now, for aiming (one frame, not averaged; same format).
  virtual cv::Mat preview() { return capture(); }
};

}  // namespace lfd::live
