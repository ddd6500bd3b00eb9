#pragma once
// The photographs of a calibration: one folder per camera position, one image per pattern
// (DIR/captures/<position>/<pattern stem>.<ext>), read as float RGB.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "sim/patterns.hpp"
#include "util/image.hpp"

namespace lfd::sim {

// The photographs of one camera position, by pattern file stem. Images are CV_32FC3, RGB,
// values in [0, 1].
struct PositionCaptures {
  std::string name;
  std::map<std::string, cv::Mat> images;
  std::map<std::string, std::string> paths;  // for messages (the stem if not from disk)

  // The photograph of pattern `stem`; InputError if there is none.
  const cv::Mat& image(const std::string& stem) const;
  // Its file (or "<position>/<stem>" when it did not come from disk), for messages.
  std::string path(const std::string& stem) const;
};

// Reads DIR/captures/<position>/<pattern stem>.<any extension OpenCV reads>. Throws
// InputError for a missing capture, a duplicate, an unreadable file or mixed image sizes;
// files that match no pattern are skipped with a warning.
std::vector<PositionCaptures> read_captures(const std::filesystem::path& dir,
                                            const PatternSet& set,
                                            std::vector<std::string>& warnings);

// One photograph as CV_32FC3 RGB in [0, 1] (8- or 16-bit, grey, BGR or BGRA files). EXIF
// orientation is not applied: a phone's photos keep the sensor's orientation, so a camera
// file and the photos it is used with agree. InputError naming the file if unreadable.
cv::Mat read_capture(const std::filesystem::path& path);

// cv::Mat (CV_32FC3 RGB) <-> the project's float images.
cv::Mat to_mat(const ImageF& image);
// 8-bit grey of a float RGB photo (what the marker and board detectors take).
cv::Mat to_gray8(const cv::Mat& rgb);

}  // namespace lfd::sim
