#pragma once
// Small panels with real lenses, so the interlace tests stay fast: LKG-2K's lens on 320x200, and
// the 16" portrait Gen3 template (subpixel cells) on 216x384.
#include "display/calibration_file.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::interlace::test_displays {

inline display::DisplayCalibration small_display() {
  return display::parse_visual_json(
      R"({"pitch":{"value":47.56401443481445},"slope":{"value":-5.48},"center":{"value":0.374},)"
      R"("viewCone":{"value":40},"invView":{"value":1},"DPI":{"value":338},)"
      R"("screenW":{"value":320},"screenH":{"value":200},"fringe":{"value":0.1}})",
      "small");
}

inline display::DisplayCalibration small_gen3_display() {
  display::DisplayCalibration c =
      display::read_calibration(test::fixture_calibration("template-16in-portrait-gen3.visual.json")).display;
  c.screen_w = 216;
  c.screen_h = 384;
  return c;
}

}  // namespace lfd::interlace::test_displays
