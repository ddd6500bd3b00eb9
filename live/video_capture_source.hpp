#pragma once
// The live calibration's camera (live/live_devices.hpp): a cv::VideoCapture device (a UVC
// webcam or a camera in webcam mode). Phase decoding compares the brightness of one camera
// pixel across patterns, so the camera must not adapt between them: automatic exposure,
// white balance and focus run automatically while the user aims (the preview), settle on the
// white pattern before the session's first photograph and are then locked for the whole
// session (best effort: a backend that refuses is named in a warning). Each photograph averages a
// few frames (noise / sqrt(n)) taken after the frames buffered before the pattern changed.
#include <functional>
#include <optional>
#include <set>
#include <string>

#include <opencv2/videoio.hpp>

#include "live/live_devices.hpp"

namespace lfd::live {

struct VideoCaptureOptions {
  int index = 0;                        // /dev/video<index>
  int frames_averaged = 4;
  std::optional<cv::Size> frame_size;   // ask for this size (the intrinsics' size), else 1920x1080
  bool manage_settings = true;          // false: leave exposure, white balance, focus as set
  std::function<void(const std::string&)> warn;  // settings the backend refused, once each
};

class VideoCaptureSource : public FrameSource {
 public:
  // Opens the camera (V4L2, else any backend) with automatic exposure, white balance and
  // focus on; throws InputError naming the index when there is no such camera.
  explicit VideoCaptureSource(VideoCaptureOptions options);

  // Nothing to do: locked settings stay locked (one focus and exposure per session).
  void start_position(int index, int count) override;
  // Lets the automatic settings settle on the white pattern, then locks them at the values
  // reached (once per session).
  void fix_exposure_on_white() override;
  cv::Mat capture() override;
  cv::Mat preview() override { return read_frame(); }

  // "camera 0 (V4L2): 1920x1080" (for the log).
  std::string describe();

 private:
  cv::Mat read_frame();  // one frame, CV_32FC3 RGB in [0, 1]
  void set(int property, double value, const char* what);

  VideoCaptureOptions options_;
  cv::VideoCapture capture_;
  int buffered_frames_ = 4;
  std::set<std::string> refused_;
};

}  // namespace lfd::live
