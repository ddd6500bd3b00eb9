// The calibration and default quilt the clients read (docs/serve.md).
#include "serve/served_display_json.hpp"

#include "display/visual_json.hpp"

namespace lfd::serve {

nlohmann::json served_calibration(const ServedDisplay& d) {
  nlohmann::json cal = nlohmann::json::parse(display::to_visual_json(d.calibration.display).dump());
  const auto ensure = [&](const char* key, nlohmann::json value) {
    if (!cal.contains(key)) cal[key] = std::move(value);
  };
  ensure("configVersion", "1.0");
  ensure("serial", d.calibration.display.serial);
  ensure("fringe", {{"value", d.calibration.display.fringe}});
  ensure("subpixelCells", nlohmann::json::array());
  if (!cal.contains("CellPatternMode") && !cal.contains("cellPatternMode"))
    cal["CellPatternMode"] = {{"value", d.calibration.display.cell_pattern_mode}};
  cal["calibrationSource"] = d.calibration_source;
  return cal;
}

nlohmann::json served_default_quilt(const ServedDisplay& d) {
  return {{"quiltAspect", d.default_quilt.aspect},
          {"quiltX", d.quilt_width_px},
          {"quiltY", d.quilt_height_px},
          {"tileX", d.default_quilt.cols},
          {"tileY", d.default_quilt.rows}};
}

}  // namespace lfd::serve
