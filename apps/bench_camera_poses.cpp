// lfd bench camera-poses: how many board poses the camera calibration needs
// (docs/calibration.md, "How many poses").
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "pipeline/camera_pose_count.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {

int RunBenchCameraPoses(int argc, char** argv) {
  CLI::App app{"The focal length's error and OpenCV's sigma when `lfd camera calibrate` sees the\n"
               "first N of 12 tilted board poses (k3 free and fixed), and 8 head-on ones:\n"
               "synthesized 640x480 photos of the default board by a known camera.\n"
               "\nExample:\n  lfd bench camera-poses --json camera_poses.json",
               "camera-poses"};
  std::string json_path;
  int max_tilted = 12;
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  app.add_option("--max-poses", max_tilted, "the most tilted poses to calibrate from")
      ->capture_default_str()
      ->check(CLI::Range(3, 12));
  if (auto code = parse(app, argc, argv)) return *code;

  const auto rows = pipeline::measure_camera_pose_count(max_tilted);
  std::printf("| poses | k3 | fx error %% | fx 1-sigma %% | cx error px | cy error px | RMS px | advice |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for (const auto& r : rows)
    std::printf("| %s | %s | %+.3f | %.3f | %+.2f | %+.2f | %.3f | %s |\n", r.poses.c_str(),
                r.fix_k3 ? "fixed" : "free", r.fx_error_pct, r.fx_sigma_pct, r.cx_error_px,
                r.cy_error_px, r.rms_px, r.pose_advice ? "not varied" : "-");
  if (!json_path.empty()) {
    nlohmann::ordered_json j = {{"benchmark", "camera-poses"},
                                {"rows", nlohmann::ordered_json::array()}};
    for (const auto& r : rows)
      j["rows"].push_back({{"poses", r.poses},
                           {"count", r.count},
                           {"fix_k3", r.fix_k3},
                           {"fx_error_pct", r.fx_error_pct},
                           {"fx_sigma_pct", r.fx_sigma_pct},
                           {"cx_error_px", r.cx_error_px},
                           {"cy_error_px", r.cy_error_px},
                           {"rms_px", r.rms_px},
                           {"pose_advice", r.pose_advice}});
    write_text_atomic(json_path, j.dump(2) + "\n");
    std::printf("wrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
