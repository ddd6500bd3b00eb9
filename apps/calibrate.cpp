// lfd calibrate: a display unit's calibration from photographs of `lfd patterns`
// (docs/calibration.md). Thin: the pipeline is calib::calibrate_display.
#include <cstdio>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "calib/calibrate.hpp"
#include "calib/solve_plan.hpp"
#include "calib/undescribed.hpp"
#include "util/atomic_file.hpp"
#include "live/hardware_live_calibration.hpp"
#include "live/live_calibration.hpp"
#include "live/live_session.hpp"
#include "util/error.hpp"
#include "report/calibration_report.hpp"

namespace lfd::apps {

namespace {

// The command line of `lfd calibrate`, as parsed.
struct CalibrateArgs {
  std::string dir, camera_path, out_path, visual_path, report_dir, simulate_path, monitor, resume_dir;
  std::filesystem::path solved_dir;  // the capture folder whose patterns were solved last
  bool force = false, live = false, keep_camera_settings = false, no_preview = false;
  int camera_index = 0, grid = 8, positions = 1, rounds = 2;
  calib::CalibrateOptions options;
  DisplaySource display_source;
  // The cover layer (resolved into options.cover by resolve_cover).
  std::optional<double> cover_thickness_m, cover_sigma_m, cover_index;
  std::vector<double> cover_range_m;
  bool cover_unknown = false;
};

// Options: every flag of `lfd calibrate`, mapped onto CalibrateArgs.
void add_calibrate_options(CLI::App& app, CalibrateArgs& a) {
  calib::CalibrateOptions& options = a.options;
  app.add_option("DIR", a.dir,
                 "folder with patterns/ and captures/, or a live session's folder (its last "
                 "round); with --live, where the session saves its photos (default: "
                 "live-capture beside --out), or a panel nobody described: the lens probes of "
                 "`lfd patterns --screen` in DIR/patterns (the session goes to DIR/live)");
  app.add_option("--camera", a.camera_path,
                 "camera intrinsics (OpenCV YAML: camera_matrix, distortion_coefficients); "
                 "without it they are self-calibrated from the board at >= 3 positions");
  a.display_source.add(app, "--display",
                       "display description (default: the one in the pattern manifest); with "
                       "--device, the unit's factory calibration is the nominal to start from",
                       false);
  app.add_option("--out", a.out_path, "calibration.json to write")->required();
  app.add_option("--visual-json", a.visual_path, "also export the lens values as visual.json");
  app.add_option("--report", a.report_dir, "write the report here: index.html (result, gates, per-position tables, phase and residual maps), figures, report.json");
  app.add_option("--grid", a.grid, "correction field control points per side (0: none)")
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
  auto* thickness = app.add_option(
      "--cover-thickness", a.cover_thickness_m,
      "the cover (acrylic block, glass) in front of the lenses, metres: measured, held unless "
      "--cover-sigma (default: the family's estimate with its tolerance; for a panel nobody "
      "described, what `lfd patterns` was given, else unknown)");
  app.add_option("--cover-sigma", a.cover_sigma_m,
                 "the --cover-thickness's 1-sigma, metres: the photos refine it where they can, "
                 "the rest goes into every sigma")
      ->check(CLI::Range(0.0, 0.5))
      ->needs(thickness);
  auto* range = app.add_option("--cover-range", a.cover_range_m,
                               "the cover lies between MIN and MAX metres (a uniform prior)")
                    ->expected(2);
  auto* unknown = app.add_flag("--cover-unknown", a.cover_unknown,
                               "nothing is known of the cover: 0-25 mm (a uniform prior)");
  thickness->excludes(range)->excludes(unknown);
  range->excludes(unknown);
  app.add_option("--cover-index", a.cover_index, "the cover's refractive index (default 1.49)")
      ->check(CLI::Range(1.0, 3.0));
  app.add_flag("--force", a.force, "replace existing outputs (a .bak is kept)");
  app.add_flag("--live", a.live, "show patterns on the display and grab camera frames");
  app.add_option("--monitor", a.monitor,
                 "live: monitor name prefix (default LKG; else the display's resolution decides)");
  app.add_option("--camera-index", a.camera_index, "live: OpenCV camera index (/dev/videoN)")
      ->capture_default_str();
  app.add_option("--positions", a.positions,
                 "live: camera positions per round (you are asked to move the camera)")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  app.add_option("--rounds", a.rounds, "live: rounds, each with patterns for the last estimate")
      ->capture_default_str()
      ->check(CLI::Range(1, 10));
  app.add_flag("--keep-camera-settings", a.keep_camera_settings,
               "live: leave exposure, white balance and focus as set (v4l2-ctl) instead of "
               "letting them settle on the white pattern and locking them");
  app.add_option("--resume", a.resume_dir,
                 "live: resume the session saved in this folder (positions already complete "
                 "are not photographed again)");
  app.add_flag("--no-preview", a.no_preview,
               "live: no camera preview while aiming (the console prompt alone)");
  app.add_option("--simulate", a.simulate_path,
                 "live: run against the simulator with this TRUE calibration");
}

// The cover options into options.cover (unset when none is given: the description's).
void resolve_cover(CalibrateArgs& a) {
  const double index = a.cover_index.value_or(display::CoverLayer{}.refractive_index);
  if (a.cover_unknown) {
    a.options.cover = calib::CoverGiven::unknown(index);
  } else if (a.cover_range_m.size() == 2) {
    const double lo = a.cover_range_m[0], hi = a.cover_range_m[1];
    if (!(lo >= 0 && hi >= lo && hi < 0.5))
      throw_input_error("--cover-range {} {}: needs 0 <= MIN <= MAX < 0.5 metres", lo, hi);
    a.options.cover = calib::CoverGiven::range(
        lo, hi, index, fmt::format("between {:g} and {:g} mm", 1e3 * lo, 1e3 * hi));
  } else if (a.cover_thickness_m) {
    if (!(*a.cover_thickness_m >= 0 && *a.cover_thickness_m < 0.5))
      throw_input_error("--cover-thickness {}: needs 0 <= M < 0.5 metres", *a.cover_thickness_m);
    calib::CoverGiven c;
    c.cover = {*a.cover_thickness_m, index};
    c.sigma_m = a.cover_sigma_m.value_or(0.0);
    c.said = c.sigma_m > 0 ? fmt::format("{:g} +- {:g} mm as given", 1e3 * c.cover.thickness_m,
                                         1e3 * c.sigma_m)
                           : fmt::format("{:g} mm as given, held", 1e3 * c.cover.thickness_m);
    a.options.cover = c;
  } else if (a.cover_index) {
    throw_input_error("--cover-index needs --cover-thickness, --cover-range or --cover-unknown");
  }
}

// Checks: fail before the work, not after it.
void check_outputs_and_read_camera(CalibrateArgs& a) {
  resolve_cover(a);
  for (const auto& p : {a.out_path, a.visual_path})
    if (!p.empty() && std::filesystem::exists(p) && !a.force)
      throw_input_error("{}: exists; pass --force to replace it (a .bak is kept)", p);
  if (!a.camera_path.empty()) a.options.camera = sim::CameraIntrinsics::read_yaml(a.camera_path);
  a.options.solver.grid_nx = a.options.solver.grid_ny = a.grid < 4 ? 0 : a.grid;
}

void print_probe_lens(const calib::ProbeLensEstimate& lens);

// The call, live: patterns shown on the display (or the simulator) and photographed now.
// `reference`: the unit's own description, which the report compares the recovered lens with.
calib::CalibrationOutcome calibrate_live(CalibrateArgs& a,
                                         std::optional<report::ReferenceCalibration>& reference) {
  const calib::CalibrateOptions& options = a.options;
  live::LiveOptions lo;
  lo.calibrate = options;
  lo.monitor_prefix = a.monitor.empty() ? "LKG" : a.monitor;
  lo.camera_index = a.camera_index;
  lo.positions = a.positions;
  lo.rounds = a.rounds;
  lo.lock_camera_settings = !a.keep_camera_settings;
  lo.preview = !a.no_preview;
  // Saved as they are taken, so the run can be re-solved offline and resumed.
  if (!a.resume_dir.empty() && !std::filesystem::exists(a.resume_dir + "/live-session.json"))
    throw_input_error("--resume {}: no live session there (live-session.json)", a.resume_dir);
  // A panel nobody described: DIR holds its lens probes (`lfd patterns --screen`), which round
  // 1 shows; the session is saved beside them.
  if (!a.dir.empty() &&
      std::filesystem::exists(std::filesystem::path(a.dir) / "patterns" / "manifest.json")) {
    sim::PatternSet coarse = sim::read_pattern_set(a.dir);
    if (!coarse.undescribed)
      throw_input_error("{}/patterns: a described pattern set; --live draws its own patterns "
                        "from --display (give DIR only for a panel nobody described, or as "
                        "the session's folder)",
                        a.dir);
    lo.probes = std::move(coarse);
    live::check_live_plan(lo);
  }
  lo.session_dir = !a.resume_dir.empty() ? std::filesystem::path(a.resume_dir)
                   : lo.probes           ? std::filesystem::path(a.dir) / "live"
                   : !a.dir.empty()      ? std::filesystem::path(a.dir)
                                         : std::filesystem::path(a.out_path).parent_path() / "live-capture";
  if (std::filesystem::exists(lo.session_dir / "live-session.json"))
    std::fprintf(stderr, "resuming the live session in %s\n", lo.session_dir.string().c_str());
  if (!lo.probes && !a.display_source.given())
    throw_input_error("--live needs --display or --device (the nominal description to start "
                      "from), or DIR with the lens probes of a panel nobody described (`lfd "
                      "patterns --screen WxH --dpi D --out DIR`)");
  if (lo.probes && a.display_source.given())
    throw_input_error("--live {}: the panel's lens probes, or --display: not both", a.dir);
  const display::Calibration nominal = lo.probes ? lo.probes->nominal : a.display_source.load();
  // What the gates would refuse after every photo is taken is refused before anything is shown.
  calib::plan_solves({nominal, size_t(a.positions), /*live=*/true}, options);
  if (!lo.probes) reference = report::ReferenceCalibration{nominal, a.display_source.name()};
  lo.on_probes = [](const calib::ProbeRound& found) { print_probe_lens(found.lens); };
  calib::CalibrationOutcome outcome =
      a.simulate_path.empty()
          ? live::run_live_calibration_on_hardware(nominal, lo)
          : live::run_live_calibration_simulated(
                nominal, display::read_calibration(a.simulate_path), lo);
  a.solved_dir = live::capture_folder_of(lo.session_dir);
  return outcome;
}

// The call, offline: the photographs in DIR (a live session's folder: its last round).
calib::CalibrationOutcome calibrate_from_folder(
    CalibrateArgs& a, std::optional<report::ReferenceCalibration>& reference) {
  std::string& dir = a.dir;
  if (dir.empty()) throw_input_error("DIR is required (or --live)");
  dir = live::capture_folder_of(dir).string();  // a live session: its last round
  // A live session's round keeps the intrinsics it was solved with.
  if (!a.options.camera && std::filesystem::exists(dir + "/camera.yaml")) {
    a.options.camera = sim::CameraIntrinsics::read_yaml(dir + "/camera.yaml");
    std::fprintf(stderr, "camera intrinsics from %s/camera.yaml\n", dir.c_str());
  }
  const sim::PatternSet set = sim::read_pattern_set(dir);
  if (a.display_source.given()) {
    const display::Calibration d = a.display_source.load();
    reference = report::ReferenceCalibration{d, a.display_source.name()};
    if (d.display.screen_w != set.nominal.display.screen_w ||
        d.display.screen_h != set.nominal.display.screen_h)
      throw_input_error("{}: is {}x{}, the patterns were made for {}x{}", a.display_source.name(),
                        d.display.screen_w, d.display.screen_h, set.nominal.display.screen_w,
                        set.nominal.display.screen_h);
  }
  std::vector<std::string> warnings;
  const auto captures = sim::read_captures(dir, set, warnings);
  a.solved_dir = dir;
  calib::CalibrationOutcome outcome = calib::calibrate_display(set, captures, a.options);
  outcome.warnings.insert(outcome.warnings.begin(), warnings.begin(), warnings.end());
  return outcome;
}

// What the probes showed.
void print_probe_lens(const calib::ProbeLensEstimate& lens) {
  std::printf("lens from the probes (%s): pitch %.4f lpi, slant %+.4f deg (slope %.5f), %s "
              "stripes; probe %d, moire %.1f times its surroundings\n",
              lens.position.c_str(), lens.pitch_lpi, lens.slant_deg, lens.slope,
              lens.bgr ? "BGR" : "RGB", lens.chosen.probe, lens.chosen.strength);
}

// A panel nobody described, step 1 (DIR holds the probes' photos, DIR/fine nothing yet): the
// lens from the probes, and the fine set drawn for it in DIR/fine. Nothing else is written.
void measure_probes_and_draw_fine_set(const std::string& dir, const sim::PatternSet& coarse) {
  calib::check_probe_photos(dir, coarse);
  std::vector<std::string> warnings;
  const auto captures = sim::read_captures(dir, coarse, warnings);
  for (const auto& w : warnings) std::cerr << "warning: " << w << "\n";
  const calib::ProbeRound round = calib::fine_set_from_probes(coarse, captures.front());
  const calib::ProbeLensEstimate& lens = round.lens;
  const sim::PatternSet& fine = round.fine;
  const auto fine_dir = calib::fine_folder(dir);
  sim::write_pattern_set(fine_dir, fine, false);
  print_probe_lens(lens);
  std::printf("wrote the fine set for it to %s/patterns (%zu patterns)\nnext: photograph them "
              "from 2-3 positions at clearly different distances (%s/captures/<position>/), "
              "then run `lfd calibrate %s` again\n",
              fine_dir.string().c_str(), fine.patterns.size(), fine_dir.string().c_str(),
              dir.c_str());
}

// Printing: the warnings, the report (written even when a gate fails, to show why), the
// gates, then the calibration files and its figures.
void report_and_write(const CalibrateArgs& a, const calib::CalibrationOutcome& outcome,
                      const std::optional<report::ReferenceCalibration>& reference) {
  for (const auto& w : outcome.warnings) std::cerr << "warning: " << w << "\n";
  if (outcome.colour_order.best == outcome.colour_order.given &&
      !outcome.colour_order.finding.empty())
    std::cerr << outcome.colour_order.finding << "\n";
  if (!a.report_dir.empty())
    report::write_calibration_report(outcome, a.report_dir, reference ? &*reference : nullptr);
  calib::enforce_gates(outcome);

  const auto& c = outcome.calibration;
  display::write_calibration(a.out_path, c, a.force);
  if (!a.visual_path.empty()) display::export_visual_json(a.visual_path, c, a.force);
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
  std::printf("%s\n", calib::cover_summary(outcome).c_str());
  std::printf("wrote %s\n", a.out_path.c_str());
}

}  // namespace

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
  CalibrateArgs args;
  add_calibrate_options(app, args);
  if (auto code = parse(app, argc, argv)) return *code;
  check_outputs_and_read_camera(args);
  // A panel nobody described: its probes first, then (DIR/fine photographed) the fine set.
  if (!args.live && !args.dir.empty() &&
      std::filesystem::exists(std::filesystem::path(args.dir) / "patterns" / "manifest.json")) {
    const sim::PatternSet coarse = sim::read_pattern_set(args.dir);
    if (coarse.undescribed) {
      const auto fine = calib::fine_folder(args.dir);
      if (!std::filesystem::exists(fine / "captures")) {
        measure_probes_and_draw_fine_set(args.dir, coarse);
        return 0;
      }
      args.dir = fine.string();
    }
  }
  // The unit's own description (its factory calibration with --device): the report compares
  // the recovered lens with it.
  std::optional<report::ReferenceCalibration> reference;
  const calib::CalibrationOutcome outcome =
      args.live ? calibrate_live(args, reference) : calibrate_from_folder(args, reference);
  // The fine set of a panel nobody described (offline or live): what was measured, assumed.
  if (const sim::PatternSet solved = sim::read_pattern_set(args.solved_dir);
      calib::from_probes(solved)) {
    auto what = calib::undescribed_report(solved.nominal, calib::assumptions_of(solved));
    what["cover"] = calib::cover_report(outcome);
    std::printf("undescribed panel: %s\n", what.dump().c_str());
    if (!args.report_dir.empty()) {
      std::filesystem::create_directories(args.report_dir);
      write_text_atomic(std::filesystem::path(args.report_dir) / "undescribed.json",
                        what.dump(2) + "\n");
    }
  }
  report_and_write(args, outcome, reference);
  return 0;
}

}  // namespace lfd::apps
