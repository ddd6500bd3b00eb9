#include "pipeline/capture_cache.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "util/atomic_file.hpp"

namespace lfd::pipeline {

std::vector<sim::PositionCaptures> cached_captures(const std::filesystem::path& cache_dir,
                                                     const std::string& key,
                                                     const sim::PatternSet& set,
                                                     const display::Calibration& truth,
                                                     const sim::CaptureRig& rig) {
  namespace fs = std::filesystem;
  if (cache_dir.empty()) return sim::simulate_captures(set, truth, rig);
  const fs::path dir = cache_dir / key;
  if (fs::exists(dir / "complete")) {
    std::vector<std::string> warnings;
    return sim::read_captures(dir, set, warnings);
  }
  auto captures = sim::simulate_captures(set, truth, rig);
  for (const auto& pc : captures) {
    const fs::path pdir = dir / "captures" / pc.name;
    fs::create_directories(pdir);
    for (const auto& [stem, image] : pc.images) {
      cv::Mat bgr, out;
      cv::cvtColor(image, bgr, cv::COLOR_RGB2BGR);
      bgr.convertTo(out, CV_16UC3, 65535.0);
      cv::imwrite((pdir / (stem + ".png")).string(), out);
    }
  }
  // Written last: a run cut short leaves no "complete" marker and is simulated again.
  write_text_atomic(dir / "complete", "");
  return captures;
}

}  // namespace lfd::pipeline
