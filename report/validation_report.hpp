#pragma once
// The validation report: validation.json (profiles, X_i, V_i, means), gnuplot figures
// (angular profiles, per-view crosstalk and separation) and index.html showing them.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "validate/view_metrics.hpp"
#include "validate/view_profiles.hpp"

namespace lfd::report {

// One measured configuration: what the interlacer assumed against the true optics.
struct ValidationCase {
  std::string name;                 // e.g. "assumed", "true"
  std::string truth_source;         // file names, for the record
  std::string assumed_source;
  validate::ViewProfiles profiles;
  validate::ViewSummary summary;
};

nlohmann::ordered_json to_json(const ValidationCase& c);

// Writes validation.json, the figures and index.html into `dir` (created if needed); every
// file atomically. Returns the path of index.html.
std::filesystem::path write_report(const std::filesystem::path& dir,
                                   const std::vector<ValidationCase>& cases);

}  // namespace lfd::report
