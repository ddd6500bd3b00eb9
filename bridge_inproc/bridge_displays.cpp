#include "bridge_inproc/bridge_displays.hpp"

#include <array>

#include "device/device_discovery.hpp"
#include "display/cover_layer.hpp"
#include "display/display_quilt.hpp"
#include "util/error.hpp"

namespace lfd::bridge {

namespace {

// lfd's device-type numbers, by display::cover_layer_for_family's family names (the vendor's
// hw_enum values are not public).
constexpr std::array<const char*, 8> kFamilies = {"Gen1 8.9\"", "Gen1 15.6\"", "Portrait", "16\" Gen2",
                                                  "32\" Gen2", "16\" Gen3 portrait", "16\" Gen3 landscape", "Go"};

}  // namespace

BridgeDisplay bridge_display_of(const display::Calibration& calibration, const std::string& source) {
  BridgeDisplay d;
  d.calibration = calibration;
  d.serial = calibration.display.serial;
  d.source = source;
  const std::string family = display::cover_layer_for_family(calibration.display).family;
  d.name = "lfd display";
  for (size_t i = 0; i < kFamilies.size(); ++i)
    if (family == kFamilies[i]) {
      d.hw_enum = int(i) + 1;
      d.name = "Looking Glass " + family;
    }
  return d;
}

std::vector<BridgeDisplay> find_displays(const LfdBridgeSettings& settings) {
  std::vector<BridgeDisplay> out;
  for (const std::string& file : settings.calibrations)
    out.push_back(bridge_display_of(display::read_calibration(file), file));
  if (!settings.device.empty()) {
    const device::Discovery found = device::discover_devices();
    for (const device::FoundDevice& unit : found.devices) {
      if (!unit.readable()) continue;
      if (settings.device != "auto" && unit.serial != settings.device) continue;
      const display::Calibration calibration = device::calibration_of(unit);
      bool known = false;
      for (const BridgeDisplay& d : out) known |= !d.serial.empty() && d.serial == calibration.display.serial;
      if (!known) out.push_back(bridge_display_of(calibration, "device " + unit.serial));
    }
  }
  for (BridgeDisplay& d : out) d.monitor_prefix = settings.monitor;
  return out;
}

DefaultQuilt default_quilt(const display::Calibration& calibration) {
  const display::DisplayQuilt quilt = display::quilt_for_display(calibration);
  const display::ViewSize view = display::view_size_for_display(quilt);
  return {float(quilt.view_aspect), view.width * quilt.grid.cols, view.height * quilt.grid.rows, quilt.grid.cols,
          quilt.grid.rows};
}

}  // namespace lfd::bridge
