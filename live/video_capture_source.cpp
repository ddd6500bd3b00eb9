#include "live/video_capture_source.hpp"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgproc.hpp>

#include "util/error.hpp"

namespace lfd::live {
namespace {

// V4L2_CID_EXPOSURE_AUTO values; OpenCV's V4L2 backend passes CAP_PROP_AUTO_EXPOSURE through.
constexpr double kV4l2ExposureManual = 1;
constexpr double kV4l2ExposureAperturePriority = 3;
// UVC cameras converge their automatic exposure and focus within a second or two.
constexpr auto kSettleTime = std::chrono::milliseconds(2000);

}  // namespace

VideoCaptureSource::VideoCaptureSource(VideoCaptureOptions options) : options_(std::move(options)) {
  options_.frames_averaged = std::max(1, options_.frames_averaged);
  // OpenCV logs a warning for every backend that fails; the error below says what matters.
  const auto log_level = cv::utils::logging::getLogLevel();
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  const bool opened = options_.index >= 0 && (capture_.open(options_.index, cv::CAP_V4L2) ||
                                              capture_.open(options_.index, cv::CAP_ANY));
  cv::utils::logging::setLogLevel(log_level);
  if (!opened)
    throw_input_error(
        "no camera at index {} (/dev/video{} cannot be opened); list the cameras with "
        "v4l2-ctl --list-devices and pass --camera-index N",
        options_.index, options_.index);
  const cv::Size size = options_.frame_size.value_or(cv::Size(1920, 1080));
  capture_.set(cv::CAP_PROP_FRAME_WIDTH, size.width);  // the backend picks the nearest mode
  capture_.set(cv::CAP_PROP_FRAME_HEIGHT, size.height);
  // Fewer buffered frames, fewer stale ones to drop after each pattern change.
  capture_.set(cv::CAP_PROP_BUFFERSIZE, 1);
  const double buffered = capture_.get(cv::CAP_PROP_BUFFERSIZE);
  buffered_frames_ = buffered >= 1 ? int(buffered) : 4;
  if (options_.manage_settings) {  // automatic while the user aims; locked on white later
    set(cv::CAP_PROP_AUTO_EXPOSURE, kV4l2ExposureAperturePriority, "turn automatic exposure on");
    set(cv::CAP_PROP_AUTO_WB, 1, "turn automatic white balance on");
    set(cv::CAP_PROP_AUTOFOCUS, 1, "turn autofocus on");
  }
}

std::string VideoCaptureSource::describe() {
  return fmt::format("camera {} ({}): {}x{}", options_.index, capture_.getBackendName(),
                     int(capture_.get(cv::CAP_PROP_FRAME_WIDTH)),
                     int(capture_.get(cv::CAP_PROP_FRAME_HEIGHT)));
}

void VideoCaptureSource::set(int property, double value, const char* what) {
  if (capture_.set(property, value)) return;
  if (refused_.insert(what).second && options_.warn)
    options_.warn(fmt::format(
        "camera {} ({}) refused to {}; set it by hand (v4l2-ctl) before starting, or the "
        "brightness may change between patterns",
        options_.index, capture_.getBackendName(), what));
}

void VideoCaptureSource::start_position(int, int) {}

void VideoCaptureSource::fix_exposure_on_white() {
  if (!options_.manage_settings) return;
  const auto until = std::chrono::steady_clock::now() + kSettleTime;
  while (std::chrono::steady_clock::now() < until) read_frame();  // the camera adapts as it streams
  // Lock each at the value the automatic mode reached (drivers usually keep it anyway).
  const double exposure = capture_.get(cv::CAP_PROP_EXPOSURE);
  const double temperature = capture_.get(cv::CAP_PROP_WB_TEMPERATURE);
  const double focus = capture_.get(cv::CAP_PROP_FOCUS);
  set(cv::CAP_PROP_AUTO_EXPOSURE, kV4l2ExposureManual, "lock the exposure");
  if (exposure > 0) set(cv::CAP_PROP_EXPOSURE, exposure, "keep the exposure");
  set(cv::CAP_PROP_AUTO_WB, 0, "lock the white balance");
  if (temperature > 0) set(cv::CAP_PROP_WB_TEMPERATURE, temperature, "keep the white balance");
  set(cv::CAP_PROP_AUTOFOCUS, 0, "lock the focus");
  if (focus > 0) set(cv::CAP_PROP_FOCUS, focus, "keep the focus");
}

cv::Mat VideoCaptureSource::read_frame() {
  cv::Mat raw;
  if (!capture_.read(raw) || raw.empty())
    throw_input_error("camera {} stopped delivering frames (unplugged?)", options_.index);
  cv::Mat rgb;
  switch (raw.channels()) {
    case 1: cv::cvtColor(raw, rgb, cv::COLOR_GRAY2RGB); break;
    case 4: cv::cvtColor(raw, rgb, cv::COLOR_BGRA2RGB); break;
    default: cv::cvtColor(raw, rgb, cv::COLOR_BGR2RGB); break;
  }
  cv::Mat out;
  rgb.convertTo(out, CV_32FC3, raw.depth() == CV_16U ? 1.0 / 65535 : 1.0 / 255);
  return out;
}

cv::Mat VideoCaptureSource::capture() {
  // Frames queued before the pattern changed show the previous one.
  for (int i = 0; i <= buffered_frames_; ++i) capture_.grab();
  cv::Mat sum = read_frame();
  for (int i = 1; i < options_.frames_averaged; ++i) sum += read_frame();
  return sum / double(options_.frames_averaged);
}

}  // namespace lfd::live
