// lfd bench calibration: the accuracy matrix of the calibration (DESIGN section 5): for each
// display kind of the shared real calibrations, a synthetic unit (real values + a smooth warp
// of up to 0.3 period, view cone +2 degrees) is photographed by the simulator from 2-3
// positions (blur, 2 % noise, vignetting, lens distortion, 5 % glare) while showing patterns
// made for a nominal description off by 1 % in pitch, 0.5 degree in slant and a random center;
// `lfd calibrate`'s pipeline recovers it; the table lists the errors and the run times.
#include <chrono>
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <omp.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "calib/calibrate.hpp"
#include "calib/synthetic_unit.hpp"
#include "calib/display/visual_json.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {

namespace {

struct Unit {
  const char* label;
  const char* file;
};

constexpr Unit kUnits[] = {{"Gen1 8.9\"", "gen1-hid-00297.visual.json"},
                           {"Portrait", "LKG-PORT-portrait.visual.json"},
                           {"16\" Gen2", "LKG-APW92011.visual.json"},
                           {"16\" Gen3 portrait", "template-16in-portrait-gen3.visual.json"}};

// The figures the calibration must reach (the calibration issue's bars).
struct Bars {
  double slant_deg = 0.001, pitch_rel = 2e-5, center = 0.005, cone_deg = 0.5, warp = 0.01;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The simulated captures, from `cache_dir` if an earlier run with the same settings left them
// there (simulating is most of the benchmark's time), else simulated and, with a cache, saved.
std::vector<calib::PositionCaptures> cached_captures(const std::string& cache_dir,
                                                     const std::string& file, int seed, int width,
                                                     int positions, int supersample,
                                                     const calib::PatternSet& set,
                                                     const calib::Calibration& truth,
                                                     const calib::CaptureRig& rig) {
  namespace fs = std::filesystem;
  if (cache_dir.empty()) return calib::simulate_captures(set, truth, rig);
  const fs::path dir =
      fs::path(cache_dir) / fmt::format("{}-seed{}-w{}-p{}-ss{}-n{}", file, seed, width,
                                        positions, supersample, set.patterns.size());
  if (fs::exists(dir / "complete")) {
    std::vector<std::string> warnings;
    return calib::read_captures(dir, set, warnings);
  }
  auto captures = calib::simulate_captures(set, truth, rig);
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
  write_text_atomic(dir / "complete", "");
  return captures;
}

}  // namespace

int RunBenchCalibration(int argc, char** argv) {
  CLI::App app{"Calibration accuracy on synthetic captures of the four display kinds of the\n"
               "shared calibrations; prints errors against the truth and run times.\n"
               "\nExample:\n  lfd bench calibration --json bench_calibration.json",
               "calibration"};
  std::string json_path, data_dir = "../shared/data";  // from the repository root
  int width_px = 1280, positions = 3, seeds = 1, supersample = 2, board_squares = 6;
  std::string only, cache_dir;
  bool true_poses = false, show_poses = false, no_noise = false, moving_glare = false;
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  app.add_option("--data", data_dir, "folder with calibrations/*.visual.json")
      ->capture_default_str();
  app.add_option("--width", width_px, "capture width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(320, 6000));
  app.add_option("--positions", positions, "camera positions (1-3)")
      ->capture_default_str()
      ->check(CLI::Range(1, 3));
  app.add_option("--supersample", supersample, "simulator samples per camera pixel per axis")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  app.add_option("--only", only, "run only the displays whose label contains this");
  app.add_option("--board-squares", board_squares, "ChArUco squares along the short side")
      ->capture_default_str()
      ->check(CLI::Range(3, 20));
  app.add_option("--seeds", seeds, "synthetic units per display kind")
      ->capture_default_str()
      ->check(CLI::Range(1, 20));
  app.add_option("--cache", cache_dir,
                 "keep the simulated captures here (16-bit PNG) and reuse them on the next run "
                 "with the same settings");
  app.add_flag("--true-poses", true_poses,
               "diagnostic: give the solver the true camera positions (0.1 mm priors)");
  app.add_flag("--no-noise", no_noise, "diagnostic: captures without sensor noise and glare");
  app.add_flag("--moving-glare", moving_glare,
               "diagnostic: new glare in every photo instead of per position");
  app.add_flag("--show-poses", show_poses,
               "diagnostic: print each position's camera error (registration, refined)");
  if (auto code = parse(app, argc, argv)) return *code;

  const Bars bars;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  std::printf("| display | seed | positions | capture | slant err deg | pitch rel err | center err "
              "| cone err deg | warp rms err | phase rms err | gates | simulate s | calibrate s "
              "| solve s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int failures = 0;
  for (const auto& u : kUnits) {
    if (!only.empty() && std::string(u.label).find(only) == std::string::npos) continue;
    const auto real = calib::read_visual_json(std::filesystem::path(data_dir) / "calibrations" / u.file);
    for (int seed = 1; seed <= seeds; ++seed) {
      calib::SyntheticUnitOptions so;
      so.seed = uint64_t(seed);
      const calib::SyntheticUnit unit = calib::make_synthetic_unit(real, so);
      calib::PatternOptions po;
      po.board_squares_short = board_squares;
      const calib::PatternSet set = calib::plan_patterns(unit.nominal, po);
      calib::CaptureRig rig =
          calib::make_capture_rig(unit.truth.display, width_px, positions, false, uint64_t(seed));
      if (no_noise) rig.effects.noise_sigma = rig.effects.glare_fraction = 0;
      rig.glare_moves = moving_glare;
      rig.effects.supersample = supersample;
      auto t0 = std::chrono::steady_clock::now();
      const auto captures =
          cached_captures(cache_dir,
                          fmt::format("{}{}{}", u.file, no_noise ? "-no-noise" : "",
                                      moving_glare ? "-moving-glare" : ""),
                          seed, width_px, positions, supersample, set, unit.truth, rig);
      const double simulate_s = seconds_since(t0);
      calib::CalibrateOptions options;
      options.camera = rig.intrinsics;
      if (true_poses)
        for (const auto& pose : rig.poses) options.known_camera_positions_m.push_back(pose.position_m);
      t0 = std::chrono::steady_clock::now();
      nlohmann::ordered_json row = {{"display", u.label}, {"file", u.file}, {"seed", seed},
                                    {"positions", positions},
                                    {"capture", {rig.intrinsics.width, rig.intrinsics.height}}};
      try {
        const calib::CalibrationOutcome out = calib::calibrate_display(set, captures, options);
        const double calibrate_s = seconds_since(t0);
        const calib::CalibrationErrors e = calib::compare_with_truth(out.calibration, unit.truth);
        if (show_poses)
          for (size_t i = 0; i < out.positions.size(); ++i) {
            const Eigen::Vector3d t = rig.poses[i].position_m;
            const Eigen::Vector3d r = out.positions[i].camera_m - t;
            const Eigen::Vector3d f = out.positions[i].camera_refined_m - t;
            std::fprintf(stderr,
                         "  %s: camera at (%.4f, %.4f, %.4f) m; registration error (%+.2f, %+.2f, "
                         "%+.2f) mm, refined (%+.2f, -, %+.2f) mm; residual rms %.4f\n",
                         out.positions[i].name.c_str(), t.x(), t.y(), t.z(), 1e3 * r.x(),
                         1e3 * r.y(), 1e3 * r.z(), 1e3 * f.x(), 1e3 * f.z(),
                         out.positions[i].residual_rms_periods);
          }
        const bool pass = e.slant_deg <= bars.slant_deg && e.pitch_rel <= bars.pitch_rel &&
                          e.center_periods <= bars.center && e.view_cone_deg <= bars.cone_deg &&
                          e.correction_rms_periods <= bars.warp;
        failures += pass ? 0 : 1;
        std::printf("| %s | %d | %d | %dx%d | %.5f | %.2e | %.4f | %.3f | %.4f | %.4f | %s | %.1f | "
                    "%.1f | %.2f |\n",
                    u.label, seed, positions, rig.intrinsics.width, rig.intrinsics.height,
                    e.slant_deg, e.pitch_rel, e.center_periods, e.view_cone_deg,
                    e.correction_rms_periods, e.phase_rms_periods,
                    out.gate_failures.empty() ? "pass" : "REJECT", simulate_s, calibrate_s,
                    out.solve.solve_seconds);
        std::fflush(stdout);
        row["errors"] = {{"slant_deg", e.slant_deg},
                         {"pitch_rel", e.pitch_rel},
                         {"center_periods", e.center_periods},
                         {"view_cone_deg", e.view_cone_deg},
                         {"correction_rms_periods", e.correction_rms_periods},
                         {"phase_rms_periods", e.phase_rms_periods}};
        row["within_bars"] = pass;
        row["gate_failures"] = out.gate_failures;
        row["uncertainty"] = out.calibration.uncertainty;
        row["seconds"] = {{"simulate", simulate_s},
                          {"calibrate", calibrate_s},
                          {"solve", out.solve.solve_seconds}};
      } catch (const std::exception& ex) {
        ++failures;
        std::printf("| %s | %d | %d | %dx%d | failed: %s |\n", u.label, seed, positions,
                    rig.intrinsics.width, rig.intrinsics.height, ex.what());
        row["error"] = ex.what();
      }
      rows.push_back(row);
    }
  }
  std::printf("\nbars: slant <= %.3f deg, pitch <= %.0e, center <= %.3f periods, cone <= %.1f "
              "deg, warp <= %.2f periods; %d row(s) outside; %d threads\n",
              bars.slant_deg, bars.pitch_rel, bars.center, bars.cone_deg, bars.warp, failures,
              omp_get_max_threads());
  if (!json_path.empty()) {
    nlohmann::ordered_json j = {{"benchmark", "calibration"},
                                {"bars",
                                 {{"slant_deg", bars.slant_deg},
                                  {"pitch_rel", bars.pitch_rel},
                                  {"center_periods", bars.center},
                                  {"view_cone_deg", bars.cone_deg},
                                  {"correction_rms_periods", bars.warp}}},
                                {"rows", rows}};
    write_text_atomic(json_path, j.dump(2) + "\n");
  }
  return 0;
}

}  // namespace lfd::apps
