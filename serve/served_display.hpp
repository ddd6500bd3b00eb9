#pragma once
// A served display from a calibration file: lfd's calibration.json (camera-refined: it wins over
// the factory file) or a factory visual.json, and which of the two it is; the default quilt is
// the quilt lfd renders for it (display/display_quilt.hpp), so clients and `lfd render` agree.
#include <filesystem>
#include <vector>

#include "serve/display_service.hpp"

namespace lfd::serve {

// Throws InputError naming the file.
ServedDisplay served_display_from_file(int index, const std::filesystem::path& calibration_file);

ServedDisplay served_display_from(int index, const display::Calibration& calibration,
                                  const std::filesystem::path& file, bool lfd_calibration);

}  // namespace lfd::serve

namespace lfd::serve {

// The displays to serve: each device's factory calibration, replaced by a `--calibration` file
// of the same serial (camera-refined calibration.json wins over the factory file), then the
// files that match no device. Throws InputError naming a file.
std::vector<ServedDisplay> served_displays(const std::vector<std::filesystem::path>& calibration_files,
                                           const std::vector<display::Calibration>& device_calibrations);

}  // namespace lfd::serve
