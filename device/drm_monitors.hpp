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
};

// nullopt for fewer than 128 bytes or a wrong header.
std::optional<EdidSummary> parse_edid(std::span<const uint8_t> edid);

struct ConnectedMonitor {
  std::string connector;  // "DP-1" (from card0-DP-1)
  display::MonitorInfo monitor;
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

}  // namespace lfd::device
