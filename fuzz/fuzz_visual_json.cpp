// libFuzzer target: Looking Glass visual.json (display::parse_visual_json). What parses must
// also write back and read again to the same lens fields (the exact round trip the devices'
// files rely on). Any input must either parse or throw lfd::InputError; anything else (a
// crash, a sanitizer report, another exception, an allocation beyond -rss_limit_mb) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "display/visual_json.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  lfd::display::DisplayCalibration c;
  try {
    c = lfd::display::parse_visual_json(text, "fuzz.visual.json");
  } catch (const lfd::InputError&) {
    return 0;
  }
  const std::string written = lfd::display::to_visual_json(c).dump(2);
  const auto again = lfd::display::parse_visual_json(written, "fuzz.visual.json (written)");
  if (again.pitch_lpi != c.pitch_lpi || again.slope != c.slope ||
      again.center_periods != c.center_periods || again.view_cone_deg != c.view_cone_deg ||
      again.screen_w != c.screen_w || again.screen_h != c.screen_h ||
      again.subpixel_cells.size() != c.subpixel_cells.size())
    std::abort();
  return 0;
}
