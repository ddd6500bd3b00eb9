#pragma once
// Which monitor shows the display (docs/devices.md "Its monitor"): Looking Glass units report EDID
// names starting with "LKG", so the name prefix decides; when no monitor or several carry it, the
// panel's resolution does. No GLFW here: the rule is plain data in, an index out. One rule for the
// live calibration window (GLFW monitors) and `lfd device list` (EDID names from DRM).
#include <cstddef>
#include <string>
#include <vector>

namespace lfd::display {

struct MonitorInfo {
  std::string name;
  int width_px = 0, height_px = 0;  // current video mode
};

// The only monitor named `name_prefix`..., else the only one of those (or, if none is so
// named, of all monitors) at width_px x height_px. Throws InputError listing every monitor
// with its name and resolution when no monitor, or more than one, fits.
size_t choose_monitor(const std::vector<MonitorInfo>& monitors, const std::string& name_prefix,
                      int width_px, int height_px);

// "\"DP-1 LKG-P\" 1536x2048, \"eDP-1\" 1920x1080" (for messages).
std::string describe_monitors(const std::vector<MonitorInfo>& monitors);

}  // namespace lfd::display
