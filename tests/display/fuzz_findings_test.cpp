// Inputs the fuzzers found (fuzz/, docs/fuzzing.md) in the display-file parsers: each is refused
// with an InputError naming the file and the field, never undefined behaviour.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "display/calibration_file.hpp"
#include "util/error.hpp"

namespace lfd::display {
namespace {

// A valid calibration.json (fuzz/corpus/fuzz_calibration_json/gen3-cells.calibration.json).
nlohmann::ordered_json valid_calibration() {
  return nlohmann::ordered_json::parse(R"({"format":"lfd-calibration","version":1,
    "display":{"pitch":{"value":40.1},"slope":{"value":-7.2},"center":{"value":0.5},
    "viewCone":{"value":40},"DPI":{"value":283},"screenW":{"value":1536},"screenH":{"value":2048}},
    "residuals":{"rms_periods":0.01,"count":1200}})");
}

void expect_rejected_naming(const nlohmann::ordered_json& j, const std::string& field) {
  try {
    parse_calibration(j.dump(), "cal.json");
    FAIL() << "accepted: " << j.dump();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cal.json"), std::string::npos) << what;
    EXPECT_NE(what.find(field), std::string::npos) << what;
  }
}

TEST(CalibrationFileFuzzFindings, TheValidSeedParses) {
  EXPECT_EQ(parse_calibration(valid_calibration().dump(), "cal.json").residuals->count, 1200);
}

TEST(CalibrationFileFuzzFindings, AResidualCountBeyondLongIsRefused) {
  auto j = valid_calibration();
  j["residuals"]["count"] = 1e300;  // was converted to long: undefined behaviour
  expect_rejected_naming(j, "residuals.count");
  j["residuals"]["count"] = -3;
  expect_rejected_naming(j, "residuals.count");
  j["residuals"]["count"] = 2.5;
  expect_rejected_naming(j, "residuals.count");
}

TEST(CalibrationFileFuzzFindings, AVersionBeyondIntIsNotReadAsVersion1) {
  auto j = valid_calibration();
  j["version"] = 4294967297LL;  // 2^32 + 1 truncated to int was 1
  expect_rejected_naming(j, "version");
}

}  // namespace
}  // namespace lfd::display
