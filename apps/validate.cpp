// lfd validate: crosstalk and view separation of a display (docs/validation.md).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "display/calibration_file.hpp"
#include "display/view_count.hpp"
#include "interlace/interlacer.hpp"
#include "util/progress.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "validate/miscalibration.hpp"
#include "validate/seen_down_the_screen.hpp"
#include "report/validation_report.hpp"
#include "validate/view_count_check.hpp"

namespace lfd::apps {

namespace {

int RunViewCountSweep(const display::Calibration& truth, const std::string& list,
                      const validate::ProfileOptions& options, const std::string& out_dir,
                      bool json) {
  std::vector<int> counts;
  for (double v : parse_numbers(list, ',', size_t(std::count(list.begin(), list.end(), ',') + 1),
                                "--sweep-views"))
    counts.push_back(int(v));
  int total = 0;
  for (int v : counts) total += v + 1;
  Progress progress("views sweep", total);
  const validate::ViewCountSweep s = validate::sweep_view_counts(truth, counts, options, &progress);
  progress.finish();
  nlohmann::ordered_json j;
  j["recommended_views"] = s.recommended;
  j["saturation_views"] = s.saturation;
  j["blur_floor"] = s.blur_floor;
  for (const auto& p : s.points)
    j["points"].push_back({{"views", p.views}, {"parallax_blur", p.parallax_blur},
                           {"mean_separation", p.mean_separation},
                           {"mean_adjacent_crosstalk", p.mean_adjacent_crosstalk}});
  write_text_atomic(std::filesystem::path(out_dir) / "view_count_sweep.json", j.dump(2) + "\n");
  if (json) {
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::printf("| views | parallax blur (cone fraction) | blur / floor | mean V | mean X adjacent |\n"
              "|---|---|---|---|---|\n");
  for (const auto& p : s.points)
    std::printf("| %d | %.4f | %.2f | %.3f | %.3f |\n", p.views, p.parallax_blur,
                p.parallax_blur / s.blur_floor, p.mean_separation, p.mean_adjacent_crosstalk);
  std::printf("blur within 10%% of its floor from %d views; the rule recommends %d\n", s.saturation,
              s.recommended);
  return 0;
}

// What an eye at `height` above the centre, `distance` in front, sees from the bottom to the
// top of the screen (vertical parallax): printed and written as seen_down_the_screen.json.
void ReportSeenDownTheScreen(const display::Calibration& truth, double height, double distance,
                             int views, const std::string& out_dir, bool json) {
  const Eigen::Vector3d eye(0.0, height, distance);
  const auto rows = validate::seen_down_the_screen(truth, eye);
  const double top_bottom = validate::fraction_difference(rows.back().measured, rows.front().measured);
  const double predicted = validate::fraction_difference(rows.back().predicted, rows.front().predicted);
  nlohmann::ordered_json j = {{"eye_m", {eye.x(), eye.y(), eye.z()}},
                              {"top_minus_bottom", top_bottom},
                              {"top_minus_bottom_predicted", predicted},
                              {"views", views}};
  for (const auto& r : rows)
    j["rows"].push_back({{"y_m", r.y_m}, {"seen", r.measured}, {"predicted", r.predicted}});
  write_text_atomic(std::filesystem::path(out_dir) / "seen_down_the_screen.json", j.dump(2) + "\n");
  if (json) return;
  std::printf("eye at (0, %+.3f, %.3f) m, true calibration: view fraction seen down the screen\n"
              "| height m | seen (optics) | predicted |\n|---|---|---|\n", height, distance);
  for (auto it = rows.rbegin(); it != rows.rend(); ++it)
    std::printf("| %+.4f | %.4f | %.4f |\n", it->y_m, it->measured, it->predicted);
  std::printf("top - bottom: %+.4f of the cone (predicted %+.4f), %+.2f of %d views\n\n",
              top_bottom, predicted, top_bottom * views, views);
}

// The command line of `lfd validate`, as parsed.
struct ValidateArgs {
  std::string assumed_path, out_dir;
  validate::ProfileOptions options;
  bool json = false;
  DisplaySource truth_source;
  validate::Miscalibration error;
  double eye_height = 0;
  CLI::Option* eye_height_option = nullptr;
  std::string blend = "nearest";
  std::string sweep;
};

// Options: every flag, mapped onto ProfileOptions (which checks itself) and a Miscalibration.
void add_validate_options(CLI::App& app, ValidateArgs& a) {
  validate::ProfileOptions& options = a.options;
  a.truth_source.add(app, "--calibration", "TRUE calibration (calibration.json or visual.json)");
  app.add_option("--assumed", a.assumed_path, "calibration the interlacer uses (default: the true one)");
  app.add_option("--slant-error", a.error.slant_deg,
                 "instead of --assumed: the truth with its slant off by this many degrees");
  app.add_option("--pitch-error", a.error.pitch_relative,
                 "... with its pitch off by this fraction (e.g. 2e-5)");
  app.add_option("--center-error", a.error.center_periods, "... with its center off (lens periods)");
  app.add_flag("--no-correction", a.error.drop_correction,
               "... without its correction field (what a plain visual.json export shows)");
  app.add_option("--views", options.views, "views in the quilt (default: recommended for the display)");
  app.add_option("--points", options.panel_points, "panel points averaged over")
      ->capture_default_str();
  app.add_option("--angles-per-view", options.angles_per_view, "direction samples per view")
      ->capture_default_str();
  app.add_option("--psf", options.psf_sigma_phase,
                 "lens point spread sigma_A, lens periods (default: the calibration's, else 0.008)");
  app.add_option("--seed", options.seed, "seed of the panel point jitter")->capture_default_str();
  app.add_option("--distance", options.distance_m, "eye distance from the panel, metres")
      ->capture_default_str();
  a.eye_height_option = app.add_option(
      "--eye-height", a.eye_height,
      "eyes at this height above the screen centre (metres; default: level with each panel "
      "point); also prints what such an eye sees from the bottom to the top of the screen");
  app.add_option("--blend", a.blend, "the interlacer's view selection: nearest or linear")
      ->capture_default_str()
      ->check(CLI::IsMember({"nearest", "linear"}));
  app.add_option("--sweep-views", a.sweep,
                 "check the view-count rule instead: parallax blur and separation for each of these "
                 "ascending view counts, e.g. 16,24,32,45,64,96");
  app.add_flag("--json", a.json, "print the figures as JSON on stdout");
  app.add_option("--out", a.out_dir, "report directory")->required();
}

// The calibrations the interlacer is run with: --assumed or the miscalibrated truth, then the
// truth itself for comparison.
struct ValidationRun {
  std::string name, source;
  display::Calibration assumed;
};

std::vector<ValidationRun> validation_runs(const ValidateArgs& a, const display::Calibration& truth,
                                           const std::string& truth_path) {
  if (!a.assumed_path.empty() && !a.error.empty())
    throw InputError("--assumed and the --*-error options are alternatives: give one");
  std::vector<ValidationRun> runs;
  if (!a.assumed_path.empty()) runs.push_back({"assumed", a.assumed_path, display::read_calibration(a.assumed_path)});
  if (!a.error.empty())
    runs.push_back({"miscalibrated", truth_path + " with " + a.error.describe(), validate::apply(truth, a.error)});
  runs.push_back({"true", truth_path, truth});
  return runs;
}

// The call: each run's view profiles through the true optics, with a progress bar.
std::vector<report::ValidationCase> measure_cases(const std::vector<ValidationRun>& runs,
                                                  const display::Calibration& truth,
                                                  const std::string& truth_path,
                                                  const validate::ProfileOptions& options) {
  std::vector<report::ValidationCase> cases;
  for (const auto& [name, source, assumed] : runs) {
    report::ValidationCase c;
    c.name = name;
    c.truth_source = truth_path;
    c.assumed_source = source;
    Progress progress("validate " + name, options.views + 1);
    c.profiles = validate::measure_view_profiles(truth, assumed, options, &progress);
    progress.finish();
    c.summary = validate::summarise(c.profiles);
    cases.push_back(std::move(c));
  }
  return cases;
}

// Printing: the cases as JSON (without the profiles, which are in validation.json) or a table.
void print_cases(const std::vector<report::ValidationCase>& cases, const std::filesystem::path& index,
                 bool json) {
  if (json) {
    nlohmann::ordered_json j = nlohmann::ordered_json::array();
    for (const auto& c : cases) {
      auto cj = report::to_json(c);
      cj.erase("profiles");  // the profiles are in validation.json
      j.push_back(cj);
    }
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("| case | views | mean V | min V | mean X | mean X adjacent |\n|---|---|---|---|---|---|\n");
  for (const auto& c : cases)
    std::printf("| %s | %d | %.3f | %.3f | %.3f | %.3f |\n", c.name.c_str(), c.profiles.views,
                c.summary.mean_separation, c.summary.min_separation, c.summary.mean_crosstalk,
                c.summary.mean_adjacent_crosstalk);
  std::cout << "wrote " << index.string() << "\n";
}

}  // namespace

int RunValidate(int argc, char** argv) {
  CLI::App app{
      "Measure view separation: angular luminance profiles of isolated views (one quilt tile\n"
      "white, the rest black), interlaced with the ASSUMED calibration and seen through the\n"
      "optics of the TRUE one, averaged over the panel; per-view crosstalk X_i and view\n"
      "separation V_i at each view's peak. Writes validation.json, figures and index.html.\n"
      "With --assumed the true-calibration case is measured too, for comparison.\n"
      "\nExamples:\n"
      "  lfd validate --calibration LKG-APW92011.visual.json --out report/\n"
      "  lfd validate --calibration truth.json --assumed recovered.json --views 24 --out report/\n"
      "  lfd validate --calibration LKG-APW92011.visual.json --slant-error 0.01 --out report/\n"
      "  lfd validate --device auto --slant-error 0.01 --out report/",
      "validate"};
  ValidateArgs args;
  add_validate_options(app, args);
  if (auto code = parse(app, argc, argv)) return *code;
  validate::ProfileOptions& options = args.options;
  options.blend = interlace::parse_view_blend(args.blend);
  if (args.eye_height_option->count()) options.eye_height_m = args.eye_height;
  options.check();

  const display::Calibration truth = args.truth_source.load();
  const std::string truth_path = args.truth_source.name();
  if (!args.sweep.empty()) return RunViewCountSweep(truth, args.sweep, options, args.out_dir, args.json);
  if (options.views == 0) options.views = display::recommend_view_count(truth).views;
  if (options.eye_height_m) {
    std::filesystem::create_directories(args.out_dir);
    ReportSeenDownTheScreen(truth, *options.eye_height_m, options.distance_m, options.views,
                            args.out_dir, args.json);
  }
  const auto cases = measure_cases(validation_runs(args, truth, truth_path), truth, truth_path, options);
  const auto index = report::write_report(args.out_dir, cases);
  print_cases(cases, index, args.json);
  return 0;
}

}  // namespace lfd::apps
