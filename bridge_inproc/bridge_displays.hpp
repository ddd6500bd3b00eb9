#pragma once
// The displays the library drives (docs/bridge-inproc.md "Which displays"): the calibration files
// of lfd's bridge settings, and the Looking Glass units device discovery finds (as `lfd serve
// --device auto`), a file and a unit with the same serial being one display. Their index in this
// list is Bridge's display index.
#include <string>
#include <vector>

#include "bridge_inproc/bridge_settings.hpp"
#include "display/calibration_file.hpp"

namespace lfd::bridge {

struct BridgeDisplay {
  display::Calibration calibration;
  std::string name;    // "Looking Glass Portrait", or "lfd display" for a panel of no known family
  std::string serial;  // the calibration's serial
  std::string source;  // the file, or "device <serial>"
  int hw_enum = 0;     // lfd's numbering of the families (docs/bridge-inproc.md): 0 unknown
  std::string monitor_prefix = "LKG";
};

// Reads the settings' calibration files and, when its device is not "", runs discovery (a
// discovery that finds nothing is not an error: there is no display to list). InputError naming
// a file that cannot be read.
std::vector<BridgeDisplay> find_displays(const LfdBridgeSettings& settings);

BridgeDisplay bridge_display_of(const display::Calibration& calibration, const std::string& source);

// Bridge's default quilt for a display: lfd's quilt for it (display::quilt_for_display, the
// view-count rule or the calibration's recommendation) at 512-pixel-tall views, as `lfd serve`
// answers defaultQuilt.
struct DefaultQuilt {
  float aspect = 1;
  int width = 0, height = 0, cols = 0, rows = 0;
};
DefaultQuilt default_quilt(const display::Calibration& calibration);

}  // namespace lfd::bridge
