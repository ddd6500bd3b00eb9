#include "display/calibration_file.hpp"

#include <cmath>
#include <iostream>

#include "display/visual_json.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::display {

namespace {

using ojson = nlohmann::ordered_json;

std::optional<double> optional_number(const ojson& root, const char* key,
                                      const std::string& name) {
  auto it = root.find(key);
  if (it == root.end() || it->is_null()) return std::nullopt;
  require_field(it->is_number() && std::isfinite(it->get<double>()), name, key,
                "is not a finite number");
  return it->get<double>();
}

}  // namespace

Calibration parse_calibration(const std::string& text, const std::string& name) {
  const ojson root = parse_json_object(text, name);
  Calibration c;
  if (!root.contains("format")) {  // a plain Looking Glass visual.json
    c.display = visual_json_from_object(root, name);
    return c;
  }
  require_field(root["format"] == "lfd-calibration", name, "format",
                "is not \"lfd-calibration\"");
  require_field(root.contains("version") && root["version"].is_number_integer(), name, "version",
                "must be an integer");
  const long long version = root["version"].get<long long>();
  require_field(version >= 1 && version <= kCalibrationFormatVersion, name, "version",
                "unsupported calibration format version " + std::to_string(version) +
                    " (this lfd reads up to " + std::to_string(kCalibrationFormatVersion) + ")");
  require_field(root.contains("display") && root["display"].is_object(), name, "display",
                "is missing");
  c.display = visual_json_from_object(root["display"], name + ": display");
  if (root.contains("correction") && !root["correction"].is_null())
    c.correction = CorrectionField::from_json(root["correction"], name);
  c.view_cone_measured_deg = optional_number(root, "view_cone_measured_deg", name);
  c.view_cone_nominal_deg = optional_number(root, "view_cone_nominal_deg", name);
  if (c.view_cone_measured_deg) {
    require_field(*c.view_cone_measured_deg > 0 && *c.view_cone_measured_deg < 180, name,
                  "view_cone_measured_deg", "must be between 0 and 180 degrees");
    // The measured cone is the cone. Files written before the nominal was kept beside it
    // hold the nominal in display.viewCone (one that equals the measured cone names none).
    if (!c.view_cone_nominal_deg && c.display.view_cone_deg != *c.view_cone_measured_deg)
      c.view_cone_nominal_deg = c.display.view_cone_deg;
    c.display.view_cone_deg = *c.view_cone_measured_deg;
  }
  if (root.contains("cover") && !root["cover"].is_null()) {
    const auto& cover = root["cover"];
    require_field(cover.is_object(), name, "cover", "is not an object");
    c.display.cover.thickness_m =
        optional_number(cover, "thickness_m", name + ": cover").value_or(0.0);
    c.display.cover.refractive_index =
        optional_number(cover, "refractive_index", name + ": cover").value_or(1.49);
    require_field(c.display.cover.thickness_m >= 0 && c.display.cover.thickness_m < 0.2, name,
                  "cover.thickness_m", "must be in [0, 0.2) metres");
    require_field(c.display.cover.refractive_index >= 1 && c.display.cover.refractive_index < 3,
                  name, "cover.refractive_index", "must be in [1, 3)");
  }
  c.phase_blur_sigma = optional_number(root, "phase_blur_sigma", name);
  if (c.phase_blur_sigma)
    require_field(*c.phase_blur_sigma >= 0 && *c.phase_blur_sigma < 0.5, name,
                  "phase_blur_sigma", "must be in [0, 0.5) lens periods");
  if (root.contains("uncertainty")) {
    require_field(root["uncertainty"].is_object(), name, "uncertainty", "is not an object");
    for (auto& [k, v] : root["uncertainty"].items()) {
      require_field(v.is_number() && std::isfinite(v.get<double>()) && v.get<double>() >= 0,
                    name, "uncertainty." + k, "must be a non-negative number");
      c.uncertainty[k] = v.get<double>();
    }
  }
  if (root.contains("residuals")) {
    const auto& r = root["residuals"];
    require_field(r.is_object(), name, "residuals", "is not an object");
    ResidualStats s;
    s.rms_periods = optional_number(r, "rms_periods", name + ": residuals").value_or(0);
    s.median_abs_periods = optional_number(r, "median_abs_periods", name + ": residuals").value_or(0);
    s.inlier_fraction = optional_number(r, "inlier_fraction", name + ": residuals").value_or(1);
    const double count = optional_number(r, "count", name + ": residuals").value_or(0);
    require_field(count >= 0 && count <= 1e15 && count == std::floor(count), name,
                  "residuals.count", "must be a whole number of samples");
    s.count = long(count);
    c.residuals = s;
  }
  if (auto v = optional_number(root, "recommended_views", name)) {
    require_field(*v >= 1 && *v <= 1000 && *v == std::floor(*v), name, "recommended_views",
                  "must be a whole number of views between 1 and 1000");
    c.recommended_views = int(*v);
  }
  if (root.contains("view_count_rule") && root["view_count_rule"].is_string())
    c.view_count_rule = root["view_count_rule"];
  if (root.contains("provenance")) c.provenance = root["provenance"];
  return c;
}

Calibration read_calibration(const std::filesystem::path& path) {
  return parse_calibration(read_text_file(path), path.string());
}

nlohmann::ordered_json to_json(const Calibration& c) {
  ojson root;
  root["format"] = "lfd-calibration";
  root["version"] = kCalibrationFormatVersion;
  root["display"] = to_visual_json(c.display);
  if (!c.correction.empty()) root["correction"] = c.correction.to_json();
  if (c.view_cone_measured_deg) {
    // display.viewCone carries the measured cone too, so tools that read only the display
    // block (or the exported visual.json) get it.
    root["display"]["viewCone"] = ojson{{"value", *c.view_cone_measured_deg}};
    root["view_cone_measured_deg"] = *c.view_cone_measured_deg;
  }
  // The nominal cone: as given, else the display's cone if the measured one has not yet
  // replaced it in memory (it would be lost from the file otherwise).
  if (c.view_cone_nominal_deg)
    root["view_cone_nominal_deg"] = *c.view_cone_nominal_deg;
  else if (c.view_cone_measured_deg && c.display.view_cone_deg != *c.view_cone_measured_deg)
    root["view_cone_nominal_deg"] = c.display.view_cone_deg;
  // The cover is not a visual.json field: it lives beside the display block (a bare panel
  // writes none, so older files and their readers are unchanged).
  if (c.display.cover.present())
    root["cover"] = {{"thickness_m", c.display.cover.thickness_m},
                     {"refractive_index", c.display.cover.refractive_index}};
  if (c.phase_blur_sigma) root["phase_blur_sigma"] = *c.phase_blur_sigma;
  if (!c.uncertainty.empty()) {
    ojson u = ojson::object();
    for (const auto& [k, v] : c.uncertainty) u[k] = v;
    root["uncertainty"] = u;
  }
  if (c.residuals) {
    root["residuals"] = {{"rms_periods", c.residuals->rms_periods},
                         {"median_abs_periods", c.residuals->median_abs_periods},
                         {"inlier_fraction", c.residuals->inlier_fraction},
                         {"count", c.residuals->count}};
  }
  if (c.recommended_views) root["recommended_views"] = *c.recommended_views;
  if (!c.view_count_rule.empty()) root["view_count_rule"] = c.view_count_rule;
  if (!c.provenance.empty()) root["provenance"] = c.provenance;
  return root;
}

void write_calibration(const std::filesystem::path& path, const Calibration& c, bool force) {
  guard_overwrite(path, force);
  write_text_atomic(path, to_json(c).dump(2) + "\n");
}

void export_visual_json(const std::filesystem::path& path, const Calibration& c, bool force) {
  guard_overwrite(path, force);
  if (!c.correction.empty()) {
    const auto r = c.correction.range();
    std::cerr << "warning: " << path.string()
              << ": visual.json cannot hold the correction field (range " << r[0] << " .. "
              << r[1] << " lens periods); it is dropped\n";
  }
  if (c.display.cover.present())
    std::cerr << "warning: " << path.string() << ": visual.json cannot hold the cover layer ("
              << c.display.cover.thickness_m << " m, n = " << c.display.cover.refractive_index
              << "); it is dropped\n";
  // The measured cone is the cone: other tools reading the export must get it.
  DisplayCalibration display = c.display;
  if (c.view_cone_measured_deg) display.view_cone_deg = *c.view_cone_measured_deg;
  write_visual_json(path, display);
}

}  // namespace lfd::display
