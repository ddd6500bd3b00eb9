#pragma once
// The monitors connected to this machine, read from the kernel's DRM connectors
// (/sys/class/drm/card*-*/status and edid, under `root`): EDID monitor name and preferred
// resolution, the same facts GLFW gives the live calibration window, so one rule
// (display/monitor_choice.hpp) picks the display's monitor in both places.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "display/monitor_choice.hpp"

namespace lfd::device {

struct EdidSummary {
  std::string name;  // the monitor name descriptor (0xFC), e.g. "LKG01Do12HjQE"; may be empty
  int width_px = 0, height_px = 0;  // the first detailed timing (the preferred mode)
  // The image's physical size: the first detailed timing's (mm), else the basic block's (cm);
  // 0 when the monitor does not say (projectors, some TVs).
  int width_mm = 0, height_mm = 0;
};

// nullopt for fewer than 128 bytes or a wrong header.
std::optional<EdidSummary> parse_edid(std::span<const uint8_t> edid);

struct ConnectedMonitor {
  std::string connector;  // "DP-1" (from card0-DP-1)
  display::MonitorInfo monitor;
  int width_mm = 0, height_mm = 0;  // EdidSummary's
};

// Connected DRM connectors with a readable EDID, sorted by connector. Empty without DRM.
std::vector<ConnectedMonitor> connected_monitors(const std::filesystem::path& root);

// The monitor for a width_px x height_px display (choose_monitor with `name_prefix`, "LKG" by
// default), as "DP-1 \"LKG01Do12HjQE\" 1536x2048", or why none fits; the chosen monitor's
// resolution must be the panel's (either orientation).
struct MonitorMatch {
  std::string monitor;  // empty when none fits
  std::string problem;
};
MonitorMatch match_monitor(const std::vector<ConnectedMonitor>& monitors,
                           const std::string& name_prefix, int width_px, int height_px);

// A panel nobody described, from its EDID (`lfd patterns --monitor`): the one connected monitor
// whose name starts with `name_prefix` (any, if empty), its resolution and its pixels per inch
// from the physical width. InputError listing the monitors when none or several fit, or when
// the EDID gives no physical size.
struct MonitorPanel {
  std::string monitor;  // "DP-1 \"Name\" 1920x1080, 344 x 194 mm"
  int width_px = 0, height_px = 0;
  double dpi = 0;
};
MonitorPanel monitor_panel(const std::vector<ConnectedMonitor>& monitors,
                           const std::string& name_prefix);

}  // namespace lfd::device
