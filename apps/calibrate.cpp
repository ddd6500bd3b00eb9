// lfd calibrate: a display unit's calibration from photographs of `lfd patterns`
// (docs/calibration.md). Thin: the pipeline is calib::calibrate_display.
#include <cstdio>
#include <iostream>
#include <optional>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "calib/calibrate.hpp"
#include "live/hardware_live_calibration.hpp"
#include "live/live_calibration.hpp"
#include "live/live_session.hpp"
#include "util/error.hpp"
#include "report/calibration_report.hpp"

namespace lfd::apps {

int RunCalibrate(int argc, char** argv) {
  CLI::App app{
      "Calibrate a display unit from photographs: DIR/patterns (from `lfd patterns`) and\n"
      "DIR/captures/<position>/<pattern file>. Writes calibration.json (lens values, correction\n"
      "field, measured view cone, uncertainties, residuals, recommended views) only if every\n"
      "quality gate passes.\n"
      "\nExamples:\n"
      "  lfd calibrate unit42 --camera camera.yaml --out unit42/calibration.json\n"
      "  lfd calibrate unit42 --out cal.json --visual-json visual.json --report unit42/report\n"
      "  lfd calibrate --live --display nominal.json --camera camera.yaml --out cal.json\n"
      "  lfd calibrate --live --device auto --camera camera.yaml --out cal.json\n"
      "  lfd calibrate --live --display nominal.json --positions 3 --camera-index 1 \\\n"
      "      --out cal.json\n"
      "  lfd calibrate --live --resume unit42/live-capture --display nominal.json --out cal.json\n"
      "  lfd calibrate --live --simulate truth.json --display nominal.json --out cal.json",
      "calibrate"};
  std::string dir, camera_path, out_path, visual_path, report_dir, simulate_path,
      monitor, resume_dir;
  bool force = false, live = false, keep_camera_settings = false, no_preview = false;
  int camera_index = 0, grid = 8, positions = 1, rounds = 2;
  calib::CalibrateOptions options;
  app.add_option("DIR", dir,
                 "folder with patterns/ and captures/, or a live session's folder (its last "
                 "round); with --live, where the session saves its photos (default: "
                 "live-capture beside --out)");
  app.add_option("--camera", camera_path,
                 "camera intrinsics (OpenCV YAML: camera_matrix, distortion_coefficients); "
                 "without it they are self-calibrated from the board at >= 3 positions");
  DisplaySource display_source;
  display_source.add(app, "--display",
                     "display description (default: the one in the pattern manifest); with "
                     "--device, the unit's factory calibration is the nominal to start from",
                     false);
  app.add_option("--out", out_path, "calibration.json to write")->required();
  app.add_option("--visual-json", visual_path, "also export the lens values as visual.json");
  app.add_option("--report", report_dir, "write the report here: index.html (result, gates, per-position tables, phase and residual maps), figures, report.json");
  app.add_option("--grid", grid, "correction field control points per side (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 32));
  app.add_option("--view-cone", options.view_cone_deg,
                 "the display's view cone in degrees, known by other means: needed with one "
                 "camera position (two distances measure it)")
      ->check(CLI::Range(0.1, 179.9));
  app.add_option("--flip-subp", options.flip_subp,
                 "the panel's subpixel order, if not the description's: 0 RGB stripes, 1 BGR "
                 "stripes (visual.json flipSubp; drops Gen3 subpixel cells); the photos check it")
      ->check(CLI::Range(0, 1));
  app.add_flag("--estimate-colour-order", options.colour_order.estimate,
               "adopt the subpixel layout the photos favour (RGB, BGR, the description's cells) "
               "instead of refusing a description they contradict");
  app.add_flag("--force", force, "replace existing outputs (a .bak is kept)");
  app.add_flag("--live", live, "show patterns on the display and grab camera frames");
  app.add_option("--monitor", monitor,
                 "live: monitor name prefix (default LKG; else the display's resolution decides)");
  app.add_option("--camera-index", camera_index, "live: OpenCV camera index (/dev/videoN)")
      ->capture_default_str();
  app.add_option("--positions", positions,
                 "live: camera positions per round (you are asked to move the camera)")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  app.add_option("--rounds", rounds, "live: rounds, each with patterns for the last estimate")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  app.add_flag("--keep-camera-settings", keep_camera_settings,
               "live: leave exposure, white balance and focus as set (v4l2-ctl) instead of "
               "letting them settle on the white pattern and locking them");
  app.add_option("--resume", resume_dir,
                 "live: resume the session saved in this folder (positions already complete "
                 "are not photographed again)");
  app.add_flag("--no-preview", no_preview,
               "live: no camera preview while aiming (the console prompt alone)");
  app.add_option("--simulate", simulate_path,
                 "live: run against the simulator with this TRUE calibration");
  if (auto code = parse(app, argc, argv)) return *code;

  // Fail before the work, not after it.
  for (const auto& p : {out_path, visual_path})
    if (!p.empty() && std::filesystem::exists(p) && !force)
      throw_input_error("{}: exists; pass --force to replace it (a .bak is kept)", p);
  if (!camera_path.empty()) options.camera = sim::CameraIntrinsics::read_yaml(camera_path);
  options.solver.grid_nx = options.solver.grid_ny = grid < 4 ? 0 : grid;

  calib::CalibrationOutcome outcome;
  // The unit's own description (its factory calibration with --device): the report compares
  // the recovered lens with it.
  std::optional<report::ReferenceCalibration> reference;
  if (live) {
    live::LiveOptions lo;
    lo.calibrate = options;
    lo.monitor_prefix = monitor.empty() ? "LKG" : monitor;
    lo.camera_index = camera_index;
    lo.positions = positions;
    lo.rounds = rounds;
    lo.lock_camera_settings = !keep_camera_settings;
    lo.preview = !no_preview;
    // Saved as they are taken, so the run can be re-solved offline and resumed.
    if (!resume_dir.empty() && !std::filesystem::exists(resume_dir + "/live-session.json"))
      throw_input_error("--resume {}: no live session there (live-session.json)", resume_dir);
    lo.session_dir = !resume_dir.empty() ? std::filesystem::path(resume_dir)
                     : !dir.empty()      ? std::filesystem::path(dir)
                                         : std::filesystem::path(out_path).parent_path() / "live-capture";
    if (std::filesystem::exists(lo.session_dir / "live-session.json"))
      std::fprintf(stderr, "resuming the live session in %s\n", lo.session_dir.string().c_str());
    if (!display_source.given())
      throw_input_error("--live needs --display or --device (the nominal description to start from)");
    const display::Calibration nominal = display_source.load();
    // The cone gate would refuse the result: say so before anything is shown.
    if (options.camera && positions < 2 && !options.view_cone_deg &&
        !nominal.view_cone_measured_deg)
      throw_input_error("--positions 1: one camera position cannot measure the view cone (the "
                        "pitch absorbs its error); give it with --view-cone, or use --positions 2 "
                        "or more at different distances");
    reference = report::ReferenceCalibration{nominal, display_source.name()};
    outcome = simulate_path.empty()
                  ? live::run_live_calibration_on_hardware(nominal, lo)
                  : live::run_live_calibration_simulated(
                        nominal, display::read_calibration(simulate_path), lo);
  } else {
    if (dir.empty()) throw_input_error("DIR is required (or --live)");
    dir = live::capture_folder_of(dir).string();  // a live session: its last round
    // A live session's round keeps the intrinsics it was solved with.
    if (!options.camera && std::filesystem::exists(dir + "/camera.yaml")) {
      options.camera = sim::CameraIntrinsics::read_yaml(dir + "/camera.yaml");
      std::fprintf(stderr, "camera intrinsics from %s/camera.yaml\n", dir.c_str());
    }
    const sim::PatternSet set = sim::read_pattern_set(dir);
    if (display_source.given()) {
      const display::Calibration d = display_source.load();
      reference = report::ReferenceCalibration{d, display_source.name()};
      if (d.display.screen_w != set.nominal.display.screen_w ||
          d.display.screen_h != set.nominal.display.screen_h)
        throw_input_error("{}: is {}x{}, the patterns were made for {}x{}", display_source.name(),
                          d.display.screen_w, d.display.screen_h, set.nominal.display.screen_w,
                          set.nominal.display.screen_h);
    }
    std::vector<std::string> warnings;
    const auto captures = sim::read_captures(dir, set, warnings);
    outcome = calib::calibrate_display(set, captures, options);
    outcome.warnings.insert(outcome.warnings.begin(), warnings.begin(), warnings.end());
  }
  for (const auto& w : outcome.warnings) std::cerr << "warning: " << w << "\n";
  if (outcome.colour_order.best == outcome.colour_order.given &&
      !outcome.colour_order.finding.empty())
    std::cerr << outcome.colour_order.finding << "\n";
  if (!report_dir.empty())
    report::write_calibration_report(outcome, report_dir, reference ? &*reference : nullptr);
  calib::enforce_gates(outcome);

  const auto& c = outcome.calibration;
  display::write_calibration(out_path, c, force);
  if (!visual_path.empty()) display::export_visual_json(visual_path, c, force);
  auto sigma = [&](const char* k) {
    auto it = c.uncertainty.find(k);
    return it == c.uncertainty.end() ? 0.0 : it->second;
  };
  std::printf("pitch %.5f +- %.5f lpi, slope %.5f +- %.5f, center %.4f +- %.4f, view cone %.2f "
              "+- %.2f deg\n",
              c.display.pitch_lpi, sigma("pitch_lpi"), c.display.slope, sigma("slope"),
              c.display.center_periods, sigma("center_periods"),
              c.view_cone_measured_deg.value_or(c.display.view_cone_deg), sigma("view_cone_deg"));
  if (c.residuals)
    std::printf("phase residual rms %.4f periods (%ld samples, %.1f %% inliers); recommended "
                "views %d; %.1f s\n",
                c.residuals->rms_periods, c.residuals->count, 100 * c.residuals->inlier_fraction,
                c.recommended_views.value_or(0), outcome.seconds);
  std::printf("wrote %s\n", out_path.c_str());
  return 0;
}

}  // namespace lfd::apps
