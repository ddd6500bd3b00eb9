// The calibration's report on the console (docs/console.md, "The calibration's report").
#include "serve/calibration_report_summary.hpp"

#include <system_error>

#include "serve/bridge_request.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::serve {

using json = nlohmann::json;

namespace {

// A field of report.json, checked: `fallback` when absent, InputError when of another type.
template <typename Check>
json field(const json& j, const std::filesystem::path& file, const char* path, json fallback, Check is_right) {
  const json* v = &j;
  std::string at;
  for (std::string_view rest = path; !rest.empty();) {
    const auto dot = rest.find('.');
    const std::string key(rest.substr(0, dot));
    rest = dot == std::string_view::npos ? std::string_view() : rest.substr(dot + 1);
    if (!v->is_object() || !v->contains(key)) return fallback;
    v = &v->at(key);
  }
  if (!is_right(*v)) throw_input_error("{}: {}: not what lfd calibrate writes there", file.string(), path);
  return *v;
}

bool strings(const json& v) {
  if (!v.is_array()) return false;
  for (const json& s : v)
    if (!s.is_string()) return false;
  return true;
}

}  // namespace

std::optional<std::filesystem::path> find_calibration_report(const ServedDisplay& d) {
  if (d.calibration_source != "lfd calibration.json" || d.calibration_path.empty()) return std::nullopt;
  const std::filesystem::path folder = d.calibration_path.parent_path();
  for (const auto& candidate : {folder / "report" / "report.json", folder / "report.json"}) {
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error)) return candidate;
  }
  return std::nullopt;
}

json calibration_report_summary(const std::filesystem::path& file) {
  std::error_code error;
  const auto size = std::filesystem::file_size(file, error);
  if (error) throw_input_error("{}: cannot be read ({})", file.string(), error.message());
  if (size > kMaxCalibrationReportBytes)
    throw_input_error("{}: {} bytes, more than a report ({} at most)", file.string(), size, kMaxCalibrationReportBytes);
  const json j = parse_bounded_json(read_text_file(file), kMaxCalibrationReportBytes, file.string());
  if (!j.is_object() || !j.contains("calibration") || !j.contains("solver"))
    throw_input_error("{}: not a report of lfd calibrate (no calibration and solver)", file.string());
  const auto number = [](const json& v) { return v.is_number(); };
  const json gates = field(j, file, "gate_failures", json::array(), strings);
  const json positions = field(j, file, "positions", json::array(), [](const json& v) { return v.is_array(); });
  json summary = {{"file", file.string()},
                  {"accepted", gates.empty()},
                  {"gate_failures", gates},
                  {"warnings", field(j, file, "warnings", json::array(), strings)},
                  {"positions", positions.size()},
                  {"residual_robust_sigma_periods", field(j, file, "solver.residual_robust_sigma_periods", nullptr, number)},
                  {"termination", field(j, file, "solver.termination", "", [](const json& v) { return v.is_string(); })},
                  {"view_cone_deg", field(j, file, "calibration.display.viewCone.value", nullptr, number)},
                  {"residual_rms_periods", field(j, file, "calibration.residuals.rms_periods", nullptr, number)},
                  {"seconds", field(j, file, "seconds", nullptr, number)}};
  const auto page = file.parent_path() / "index.html";
  summary["page"] = std::filesystem::is_regular_file(page, error) ? json(page.string()) : json(nullptr);
  return summary;
}

}  // namespace lfd::serve
