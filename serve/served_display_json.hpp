#pragma once
// A display as both protocols describe it: the calibration object in visual.json's form (the
// fields holoplay-core, @lookingglass/webxr and bridge.js read, `{value: x}` wrapped) and the
// default quilt (quiltX, quiltY, tileX, tileY, quiltAspect). One definition for HoloPlay `info`
// and Bridge's `available_output_devices` (docs/serve.md).
#include <nlohmann/json.hpp>

#include "serve/display_service.hpp"

namespace lfd::serve {

// visual.json of the served calibration (lfd's calibration.json drops what visual.json cannot
// hold), with every field the clients dereference present (fringe, verticalAngle, flipImageY,
// subpixelCells, CellPatternMode) and `calibrationSource` saying which file it is.
nlohmann::json served_calibration(const ServedDisplay& display);

nlohmann::json served_default_quilt(const ServedDisplay& display);

}  // namespace lfd::serve
