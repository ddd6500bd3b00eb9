#pragma once
// Small panels with real lenses, so the tests that interlace, simulate or render a panel stay fast:
// LKG-2K's lens on 320x200 (24 x 15 mm at its 338 DPI), and the 16" portrait Gen3 template
// (subpixel cells) on 216x384.
#include <string>

#include <fmt/format.h>

#include "display/calibration_file.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::test {

// The visual.json of LKG-2K's lens on a 320x200 panel; `fringe`: the vendor's alternate-row gain
// (0: none), which the interlacer applies.
inline std::string small_lkg_2k_visual_json(double fringe = 0.0) {
  return fmt::format(
      R"({{"pitch":{{"value":47.56401443481445}},"slope":{{"value":-5.48}},"center":{{"value":0.374}},)"
      R"("viewCone":{{"value":40}},"invView":{{"value":1}},"DPI":{{"value":338}},)"
      R"("screenW":{{"value":320}},"screenH":{{"value":200}},"fringe":{{"value":{}}}}})",
      fringe);
}

inline display::DisplayCalibration small_lkg_2k(double fringe = 0.0) {
  return display::parse_visual_json(small_lkg_2k_visual_json(fringe), "small");
}

// The 16" portrait Gen3 template (two subpixel cells) on a 216x384 panel.
inline display::DisplayCalibration small_gen3_portrait_template() {
  display::DisplayCalibration c =
      display::read_calibration(fixture_calibration("template-16in-portrait-gen3.visual.json")).display;
  c.screen_w = 216;
  c.screen_h = 384;
  return c;
}

}  // namespace lfd::test
