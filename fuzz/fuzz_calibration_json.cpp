// libFuzzer target: the project's calibration.json (display::parse_calibration; also takes a
// plain visual.json), correction field included. What parses must write back (to_json) and
// read again. Any input must either parse or throw lfd::InputError; anything else (a crash,
// a sanitizer report, another exception, an allocation beyond -rss_limit_mb) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "display/calibration_file.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  lfd::display::Calibration c;
  try {
    c = lfd::display::parse_calibration(text, "fuzz.calibration.json");
  } catch (const lfd::InputError&) {
    return 0;
  }
  if (!c.correction.empty()) (void)c.correction(0.5, 0.5);
  const std::string written = lfd::display::to_json(c).dump(2);
  const auto again = lfd::display::parse_calibration(written, "fuzz.calibration.json (written)");
  if (again.display.view_cone_deg != c.display.view_cone_deg ||
      again.correction.coefficients() != c.correction.coefficients() ||
      again.recommended_views != c.recommended_views)
    std::abort();
  return 0;
}
