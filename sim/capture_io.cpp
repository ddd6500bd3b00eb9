#include "sim/capture_io.hpp"

#include <algorithm>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "util/error.hpp"

namespace lfd::sim {

cv::Mat read_capture(const std::filesystem::path& path) {
  cv::Mat raw = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  if (raw.empty()) throw_input_error("{}: not an image OpenCV can read", path.string());
  double scale = 1.0;
  switch (raw.depth()) {
    case CV_8U: scale = 1.0 / 255; break;
    case CV_16U: scale = 1.0 / 65535; break;
    case CV_32F: scale = 1.0; break;
    default: throw_input_error("{}: unsupported pixel depth", path.string());
  }
  cv::Mat rgb;
  if (raw.channels() == 1) cv::cvtColor(raw, rgb, cv::COLOR_GRAY2RGB);
  else if (raw.channels() == 3) cv::cvtColor(raw, rgb, cv::COLOR_BGR2RGB);
  else if (raw.channels() == 4) cv::cvtColor(raw, rgb, cv::COLOR_BGRA2RGB);
  else throw_input_error("{}: unsupported channel count {}", path.string(), raw.channels());
  cv::Mat out;
  rgb.convertTo(out, CV_32FC3, scale);
  return out;
}

const cv::Mat& PositionCaptures::image(const std::string& stem) const {
  auto it = images.find(stem);
  if (it == images.end()) throw_input_error("{}: missing capture of pattern {}", name, stem);
  return it->second;
}

std::string PositionCaptures::path(const std::string& stem) const {
  auto it = paths.find(stem);
  return it == paths.end() ? name + "/" + stem : it->second;
}

cv::Mat to_gray8(const cv::Mat& rgb) {
  cv::Mat gray, out;
  cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
  gray.convertTo(out, CV_8U, 255.0);
  return out;
}

cv::Mat to_mat(const ImageF& image) {
  cv::Mat out(image.height, image.width, CV_32FC3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        out.at<cv::Vec3f>(y, x)[c] = image.at(x, y, std::min(c, image.channels - 1));
  return out;
}

std::vector<PositionCaptures> read_captures(const std::filesystem::path& dir,
                                            const PatternSet& set,
                                            std::vector<std::string>& warnings) {
  namespace fs = std::filesystem;
  const fs::path root = dir / "captures";
  if (!fs::is_directory(root))
    throw_input_error("{}: no captures folder (save the photos as {}/<position>/<pattern file>)",
                      root.string(), root.string());
  std::vector<fs::path> position_dirs;
  for (const auto& e : fs::directory_iterator(root))
    if (e.is_directory()) position_dirs.push_back(e.path());
    else warnings.push_back(root.string() + ": ignoring " + e.path().filename().string() +
                            " (captures go into one folder per camera position)");
  std::sort(position_dirs.begin(), position_dirs.end());
  if (position_dirs.empty())
    throw_input_error("{}: no camera position folders (expected {}/<position>/...)",
                      root.string(), root.string());

  std::vector<PositionCaptures> out;
  for (const auto& pdir : position_dirs) {
    PositionCaptures pc;
    pc.name = pdir.filename().string();
    std::map<std::string, fs::path> found;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(pdir))
      if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      const std::string stem = f.stem().string();
      if (!set.find(stem)) {
        warnings.push_back(f.string() + ": matches no pattern in the manifest; ignored");
        continue;
      }
      if (found.count(stem))
        throw_input_error("{}: two captures of pattern {} ({} and {}); keep one", pdir.string(),
                          stem, found[stem].filename().string(), f.filename().string());
      found[stem] = f;
    }
    for (const auto& p : set.patterns) {
      const std::string stem = fs::path(p.file).stem().string();
      if (!found.count(stem))
        throw_input_error("{}: missing capture of pattern {} (expected {})", pdir.string(),
                          p.file, (pdir / p.file).string());
    }
    cv::Size size;
    for (const auto& [stem, path] : found) {
      cv::Mat img = read_capture(path);
      if (size.area() && img.size() != size)
        throw_input_error("{}: is {}x{}, the other captures of position {} are {}x{}",
                          path.string(), img.cols, img.rows, pc.name, size.width, size.height);
      size = img.size();
      pc.images[stem] = img;
      pc.paths[stem] = path.string();
    }
    out.push_back(std::move(pc));
  }
  return out;
}

}  // namespace lfd::sim
