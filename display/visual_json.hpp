#pragma once
// Reading and writing Looking Glass visual.json exactly as devices store it: numbers wrapped
// as {"value": x} (unwrapped numbers accepted on read), configVersion/serial as strings,
// Gen3 CellPatternMode (or the cellPatternMode spelling) + subpixelCells, unknown fields kept.
#include <filesystem>
#include <string>

#include "display/display_calibration.hpp"

namespace lfd::display {

// Parses JSON text that must hold an object; InputError naming `name` otherwise.
nlohmann::ordered_json parse_json_object(const std::string& text, const std::string& name);

// Parses visual.json text. `name` (usually the file path) prefixes every error message.
DisplayCalibration parse_visual_json(const std::string& text, const std::string& name);
DisplayCalibration visual_json_from_object(const nlohmann::ordered_json& root, const std::string& name);
DisplayCalibration read_visual_json(const std::filesystem::path& path);

// The visual.json object: the source object with the modelled fields updated in place
// (unchanged values keep their original form, so an untouched calibration writes back as read).
nlohmann::ordered_json to_visual_json(const DisplayCalibration& calibration);
void write_visual_json(const std::filesystem::path& path, const DisplayCalibration& calibration);

}  // namespace lfd::display
