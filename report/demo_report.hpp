#pragma once
// The demo's HTML page: what was simulated, the quilts and panels, the photographs, and the
// view-separation figures with a link to the full validation report.
#include <filesystem>
#include <string>
#include <vector>

namespace lfd::report {

struct DemoCapture {
  std::string name;
  double angle_deg = 0;
  int expected_view = 0;
  std::string scene_image, numbered_image;  // relative to the report folder
};

struct DemoValidationRow {
  std::string configuration;
  double mean_separation = 0;
  double mean_crosstalk = 0;
};

struct DemoReport {
  std::string unit_source, scene_source, calibration_note;
  size_t scene_gaussians = 0;
  int views = 0;
  std::string view_rule;
  std::vector<DemoCapture> captures;
  std::vector<DemoValidationRow> validation;
};

// Writes index.html and report.json into `dir` atomically; returns the index.html path.
std::filesystem::path write_demo_report(const std::filesystem::path& dir, const DemoReport& report);

}  // namespace lfd::report
