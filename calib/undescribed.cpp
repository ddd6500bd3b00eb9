#include "calib/undescribed.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "util/error.hpp"

namespace lfd::calib {

namespace {
constexpr const char* kSerial = "undescribed";
}

display::Calibration description_from_probes(const sim::PatternSet& coarse,
                                             const ProbeLensEstimate& lens,
                                             const UndescribedAssumptions& assumptions) {
  display::Calibration c;
  display::DisplayCalibration& d = c.display;
  d.serial = kSerial;
  d.screen_w = coarse.nominal.display.screen_w;
  d.screen_h = coarse.nominal.display.screen_h;
  d.dpi = coarse.nominal.display.dpi;
  d.pitch_lpi = lens.pitch_lpi;
  d.slope = lens.slope;
  d.center_periods = 0;
  d.view_cone_deg = assumptions.view_cone_deg;
  d.inv_view = assumptions.inv_view;
  d.flip_subp = lens.bgr;
  d.cover = assumptions.cover;
  d.check("the lens the probes measured");
  return c;
}

sim::PatternSet plan_fine_patterns(const sim::PatternSet& coarse,
                                   const display::Calibration& description) {
  sim::PatternOptions options;
  options.board_squares_short = std::min(coarse.board.squares_x, coarse.board.squares_y);
  options.fringes = coarse.fringe_steps > 0;
  return sim::plan_patterns(description, options);
}

UndescribedAssumptions assumptions_of(const sim::PatternSet& coarse) {
  return assumptions_of(coarse.nominal);
}

UndescribedAssumptions assumptions_of(const display::Calibration& nominal) {
  UndescribedAssumptions a;
  a.cover = nominal.display.cover;
  a.cover_given = a.cover.present();
  return a;
}

ProbeRound fine_set_from_probes(const sim::PatternSet& coarse,
                                const sim::PositionCaptures& captures) {
  ProbeRound r;
  r.lens = measure_lens_from_probes(coarse, captures);
  r.description = description_from_probes(coarse, r.lens, assumptions_of(coarse));
  r.fine = plan_fine_patterns(coarse, r.description);
  return r;
}

std::filesystem::path fine_folder(const std::filesystem::path& dir) { return dir / "fine"; }

void check_probe_photos(const std::filesystem::path& dir, const sim::PatternSet& coarse) {
  const auto captures = dir / "captures";
  std::error_code ec;
  bool any = false;
  for (const auto& position : std::filesystem::directory_iterator(captures, ec)) {
    if (!position.is_directory()) continue;
    std::set<std::string> stems;
    for (const auto& f : std::filesystem::directory_iterator(position.path(), ec))
      stems.insert(f.path().stem().string());
    std::map<int, std::vector<std::string>> missing;
    std::map<int, int> present;
    for (const auto& p : coarse.patterns) {
      if (p.kind != sim::PatternKind::kProbe) continue;
      const std::string stem = std::filesystem::path(p.file).stem().string();
      if (stems.count(stem)) {
        ++present[p.probe];
        any = true;
      } else {
        missing[p.probe].push_back(stem);
      }
    }
    for (const auto& [probe, stems_missing] : missing)
      if (present[probe] > 0)
        throw_input_error(
            "{}: probe {} has {} of its {} photos (missing {}): one photo of a grating cannot "
            "tell which way its moire runs, so neither the slant's sign; photograph every step",
            position.path().string(), probe, present[probe], coarse.probe_steps,
            stems_missing.front());
  }
  if (!any)
    throw_input_error("{}: no photos of the lens probes (*_probe_*): photograph every pattern of "
                      "{}/patterns from one position into {}/<position>/",
                      captures.string(), dir.string(), captures.string());
}

bool from_probes(const sim::PatternSet& set) { return from_probes(set.nominal); }

bool from_probes(const display::Calibration& nominal) { return nominal.display.serial == kSerial; }

nlohmann::ordered_json undescribed_report(const display::Calibration& probes,
                                          const UndescribedAssumptions& a) {
  const auto& d = probes.display;
  return {{"measured_by_the_probes",
           {{"pitch_lpi", d.pitch_lpi},
            {"slope", d.slope},
            {"slant_deg", display::slant_deg_of_slope(d.slope)}}},
          {"measured_by_the_fine_set",
           {"pitch", "slope", "center", "view cone", "correction field",
            "subpixel order (colour-order check, adopted)"}},
          {"assumed",
           {{"inv_view", a.inv_view},
            {"flip_image_x", false}}}};  // the cover: the calibration's report, "cover"
}

}  // namespace lfd::calib
