// libFuzzer target: the report.json of `lfd calibrate --report` as the console sums it up
// (serve::calibration_report_summary; docs/console.md "The calibration's report"). Any input must
// give a summary or throw lfd::InputError; a summary holds the facts the page reads, of their types.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz/fuzz_input_file.hpp"
#include "serve/calibration_report_summary.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = lfd::fuzz::write_input("report/report.json", data, size);
  try {
    const nlohmann::json s = lfd::serve::calibration_report_summary(file);
    if (!s.at("accepted").is_boolean() || !s.at("gate_failures").is_array() || !s.at("warnings").is_array() ||
        !s.at("positions").is_number_unsigned())
      std::abort();
    if (s.at("accepted").get<bool>() != s.at("gate_failures").empty()) std::abort();
    for (const char* number : {"residual_robust_sigma_periods", "view_cone_deg", "residual_rms_periods", "seconds"})
      if (!s.at(number).is_null() && !s.at(number).is_number()) std::abort();
  } catch (const lfd::InputError&) {
  }
  return 0;
}
