#pragma once
// The calibration's report on the console's Display view (docs/console.md): when a served
// display's calibration came from `lfd calibrate`, the report it wrote with `--report DIR`
// (docs/calibration.md, 3.6) is looked for where that command's examples put it, the folder
// `report` beside calibration.json, then the calibration's own folder; its report.json is
// summed up in a few facts (the gates' verdict, warnings, the fit) for the page.
#include <cstddef>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "serve/display_service.hpp"

namespace lfd::serve {

inline constexpr std::size_t kMaxCalibrationReportBytes = 16u << 20;

// The report.json found for `d`, or none (a factory calibration, or no report beside it).
std::optional<std::filesystem::path> find_calibration_report(const ServedDisplay& d);

// {file, accepted, gate_failures: [...], warnings: [...], positions, residual_robust_sigma_periods,
//  termination, view_cone_deg, residual_rms_periods, seconds, page} from report.json (`page`: index.html
// beside it, if there). Throws InputError naming the file and field for a report that is not
// one (not JSON, over kMaxCalibrationReportBytes, a field of the wrong type).
nlohmann::json calibration_report_summary(const std::filesystem::path& report_json);

}  // namespace lfd::serve
