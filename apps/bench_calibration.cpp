// lfd bench calibration: the accuracy matrix of the calibration (docs/calibration.md), a thin
// front end of pipeline/calibration_benchmark.hpp: prints the table and writes the JSON.
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <omp.h>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "pipeline/calibration_benchmark.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {

namespace {

// The command line of `lfd bench calibration`, as parsed.
struct BenchCalibrationArgs {
  pipeline::CalibrationBenchmarkOptions o;
  std::string json_path, data_dir = o.data_dir.string(), cache_dir;
  bool show_poses = false, above_below = false, off_axis = false;
};

// Options: every flag, mapped onto CalibrationBenchmarkOptions (which checks itself).
void add_bench_calibration_options(CLI::App& app, BenchCalibrationArgs& a) {
  pipeline::CalibrationBenchmarkOptions& o = a.o;
  app.add_option("--json", a.json_path, "write the figures as JSON to this file");
  app.add_option("--data", a.data_dir, "folder with calibrations/*.visual.json")
      ->capture_default_str();
  app.add_option("--width", o.width_px, "capture width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(320, 6000));
  app.add_option("--positions", o.positions, "camera positions (1-3)")
      ->capture_default_str()
      ->check(CLI::Range(1, 3));
  app.add_option("--supersample", o.supersample, "simulator samples per camera pixel per axis")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  app.add_option("--only", o.only, "run only the displays whose label contains this");
  app.add_option("--board-squares", o.board_squares, "ChArUco squares along the short side")
      ->capture_default_str()
      ->check(CLI::Range(3, 20));
  app.add_option("--seeds", o.seeds, "synthetic units per display kind")
      ->capture_default_str()
      ->check(CLI::Range(1, 20));
  app.add_option("--cache", a.cache_dir,
                 "keep the simulated captures here (16-bit PNG) and reuse them on the next run "
                 "with the same settings");
  app.add_flag("--true-poses", o.true_poses,
               "diagnostic: give the solver the true camera positions (0.1 mm priors)");
  app.add_flag("--no-noise", o.no_noise, "diagnostic: captures without sensor noise and glare");
  app.add_flag("--moving-glare", o.moving_glare,
               "diagnostic: new glare in every photo instead of per position");
  app.add_option("--exposure-drift", o.exposure_drift,
                 "per-photo gain drift, relative 1-sigma (a webcam that does not hold "
                 "exposure, backlight flicker), e.g. 0.03")
      ->check(CLI::Range(0.0, 0.2));
  app.add_flag("--no-exposure-fix", o.no_exposure_fix,
               "diagnostic: decode without dividing each photo's gain and offset out");
  app.add_option("--flicker", o.flicker,
                 "rolling-shutter flicker banding, relative amplitude of the gain along the "
                 "rows (phase drawn per photo), e.g. 0.08")
      ->check(CLI::Range(0.0, 0.2));
  app.add_option("--flicker-bands", o.flicker_bands, "bands of --flicker over the image height")
      ->check(CLI::Range(0.1, 100.0));
  app.add_flag("--no-row-exposure-fix", o.no_row_exposure_fix,
               "diagnostic: one gain per photo, without fitting the banding along the rows");
  app.add_flag("--above-below", a.above_below,
               "cameras above and below the screen centre (docs/calibration.md, \"With vertical parallax\"): "
               "(-0.06, +0.05, 0.45), "
               "(0.01, -0.04, 0.52), (0.07, +0.03, 0.60) m, scaled to each display's size");
  app.add_flag("--off-axis", a.off_axis,
               "the second camera 30 degrees to the right of the screen's centre, the third 25 "
               "degrees to the left (the default distances): what tells a cover's thickness")
      ->excludes("--above-below");
  app.add_flag("--solver-without-vertical-parallax", o.solver_without_vertical_parallax,
               "diagnostic: the solver models the horizontal offset alone (the captures keep "
               "the vertical parallax)");
  app.add_flag("--solver-without-cover", o.solver_without_cover,
               "diagnostic: register and solve as if the panel were bare (the captures keep "
               "the family's acrylic block or cover glass)");
  app.add_flag("--cover-unknown", o.cover_unknown,
               "tell the calibration the cover is unknown (0-25 mm) instead of the family's "
               "estimate: it estimates the thickness where the photos tell it and carries the "
               "range into every sigma");
  app.add_flag("--bare-panels", o.bare_panels,
               "diagnostic: units without a cover layer (figures before the cover was modelled)");
  app.add_flag("--self-calibrated", o.self_calibrated,
               "calibrate each unit twice from the same photos: with the camera given, then "
               "self-calibrated (no camera file); the camera column shows the focal length's "
               "error and sigma");
  app.add_flag("--undescribed", o.undescribed,
               "panels nobody described (a 10\" tablet with a positive slant, a 15.6\" 4K BGR "
               "monitor, a 20 LPI sheet): lens probes from the first position, then the fine "
               "set for the lens they find");
  app.add_flag("--show-poses", a.show_poses,
               "diagnostic: print each position's camera error (registration, refined)");
}

// The camera column: given, or self-calibrated with its focal length's error and sigma.
std::string camera_column(const pipeline::CalibrationBenchmarkRow& r) {
  return r.camera_self_calibrated
             ? (r.errors ? fmt::format("self, f {:+.2f} % +- {:.2f} %", 100 * r.focal_error_rel,
                                       100 * r.focal_sigma_rel)
                         : std::string("self"))
             : std::string("given");
}

// Diagnostic (--show-poses): where registration and refinement put each camera.
void print_poses(const pipeline::CalibrationBenchmarkRow& r) {
  for (const auto& p : r.poses)
    std::fprintf(stderr,
                 "  %s: camera at (%.4f, %.4f, %.4f) m; registration error (%+.2f, %+.2f, "
                 "%+.2f) mm, refined (%+.2f, %+.2f, %+.2f) mm; residual rms %.4f\n",
                 p.name.c_str(), p.truth_m.x(), p.truth_m.y(), p.truth_m.z(),
                 1e3 * p.registration_error_m.x(), 1e3 * p.registration_error_m.y(),
                 1e3 * p.registration_error_m.z(), 1e3 * p.refined_error_m.x(),
                 1e3 * p.refined_error_m.y(), 1e3 * p.refined_error_m.z(),
                 p.residual_rms_periods);
}

// Printing: one table row as soon as the unit is done (a run takes minutes); counts the rows
// that failed or fell outside the bars.
void print_row(const pipeline::CalibrationBenchmarkRow& r, bool show_poses, int& failures) {
  const std::string camera = camera_column(r);
  if (!r.errors) {
    ++failures;
    std::printf("| %s | %d | %d | %dx%d | %s | failed: %s |\n", r.display.c_str(), r.seed,
                r.positions, r.capture_width, r.capture_height, camera.c_str(),
                r.failure.c_str());
    std::fflush(stdout);
    return;
  }
  if (show_poses) print_poses(r);
  if (!r.probes.is_null()) std::fprintf(stderr, "  probes: %s\n", r.probes.dump().c_str());
  if (!r.cover.is_null()) std::fprintf(stderr, "  cover: %s\n", r.cover.dump().c_str());
  failures += r.within_bars ? 0 : 1;
  const auto& e = *r.errors;
  std::string ratios;
  for (const char* key : {"slant", "pitch", "center", "cone", "warp"}) {
    const auto it = r.error_over_sigma.find(key);
    ratios += it == r.error_over_sigma.end() ? std::string(" -") : fmt::format(" {:.2f}", it->second);
  }
  std::printf("| %s | %d | %d | %dx%d | %s | %.5f | %.2e | %.4f | %.3f | %.4f | %.4f | %s | %s | "
              "%.1f | %.1f | %.2f |\n",
              r.display.c_str(), r.seed, r.positions, r.capture_width, r.capture_height,
              camera.c_str(),
              e.slant_deg, e.pitch_rel, e.center_periods, e.view_cone_deg,
              e.correction_rms_periods, e.phase_rms_periods, ratios.c_str() + 1,
              r.gate_failures.empty() ? "pass" : "REJECT", r.simulate_s, r.calibrate_s,
              r.solve_s);
  std::fflush(stdout);
}

void write_json(const std::string& path, const pipeline::AccuracyBars& bars,
                const std::vector<pipeline::CalibrationBenchmarkRow>& rows) {
  nlohmann::ordered_json j = {{"benchmark", "calibration"},
                              {"bars", bars.to_json()},
                              {"rows", nlohmann::ordered_json::array()}};
  for (const auto& r : rows) j["rows"].push_back(r.to_json());
  write_text_atomic(path, j.dump(2) + "\n");
}

}  // namespace

int RunBenchCalibration(int argc, char** argv) {
  CLI::App app{"Calibration accuracy on synthetic captures of the four display kinds of the\n"
               "shared calibrations; prints errors against the truth and run times.\n"
               "\nExample:\n  lfd bench calibration --json bench_calibration.json",
               "calibration"};
  BenchCalibrationArgs args;
  add_bench_calibration_options(app, args);
  if (auto code = parse(app, argc, argv)) return *code;
  pipeline::CalibrationBenchmarkOptions& o = args.o;
  o.data_dir = args.data_dir;
  o.cache_dir = args.cache_dir;
  if (args.above_below) o.layout = sim::RigLayout::kAboveBelow;
  if (args.off_axis) o.layout = sim::RigLayout::kOffAxis;

  const pipeline::AccuracyBars bars;
  std::printf("| display | seed | positions | capture | camera | slant err deg | pitch rel err | center err "
              "| cone err deg | warp rms err | phase rms err | err/sigma slant pitch center cone "
              "warp | gates | simulate s | calibrate s | solve s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  int failures = 0;
  const auto rows = pipeline::run_calibration_benchmark(
      o, bars, [&](const pipeline::CalibrationBenchmarkRow& r) { print_row(r, args.show_poses, failures); });
  std::printf("\nbars: slant <= %.3f deg, pitch <= %.0e, center <= %.3f periods, cone <= %.1f "
              "deg, warp <= %.2f periods; %d row(s) outside; %d threads\n",
              bars.slant_deg, bars.pitch_rel, bars.center, bars.cone_deg, bars.warp, failures,
              omp_get_max_threads());
  if (!args.json_path.empty()) write_json(args.json_path, bars, rows);
  return 0;
}

}  // namespace lfd::apps
