#include "device/device_discovery.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "device/hidapi_transport.hpp"
#include "display/visual_json.hpp"
#include "util/error.hpp"

namespace lfd::device {

namespace {

bool same_serial(const std::string& a, const std::string& b) {
  return !a.empty() && a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// The panel size of a readable device (for its monitor), or the reason it is not readable.
void note_panel(FoundDevice& device) {
  try {
    const display::DisplayCalibration d = display::parse_visual_json(device.visual_json, device.source);
    device.screen_w = d.screen_w;
    device.screen_h = d.screen_h;
    if (!d.serial.empty()) device.serial = d.serial;
  } catch (const std::exception& e) {
    device.problem = e.what();
    device.visual_json.clear();
  }
}

void find_gen1_units(const DiscoveryOptions& options, Discovery& discovery) {
  const auto enumerate = options.enumerate_hid
                             ? options.enumerate_hid
                             : [] { return enumerate_hid(kGen1VendorId, kGen1ProductId); };
  const auto open = options.open_hid ? options.open_hid
                                     : [](const HidDeviceInfo& info) { return open_hid(info); };
  std::vector<std::string> paths;
  for (const HidDeviceInfo& info : enumerate()) {
    // 04d8 is Microchip's: the product string tells a HoloPlay from other Microchip devices.
    if (info.vendor_id != kGen1VendorId || info.product_id != kGen1ProductId) continue;
    if (!info.product.empty() && info.product != kGen1Product) continue;
    if (std::find(paths.begin(), paths.end(), info.path) != paths.end()) continue;
    paths.push_back(info.path);
    FoundDevice device;
    device.kind = DeviceKind::kGen1Hid;
    device.serial = info.serial;
    device.source = info.path;
    try {
      const std::unique_ptr<HidTransport> transport = open(info);
      device.visual_json = read_gen1_calibration(*transport, options.gen1);
      note_panel(device);
    } catch (const std::exception& e) {
      device.problem = e.what();
    }
    discovery.devices.push_back(std::move(device));
  }
  // Units libusb sees that hidapi could not list: say why they cannot be read.
  const UsbEnumeration usb = options.enumerate_usb ? options.enumerate_usb() : enumerate_usb_looking_glass();
  if (!usb.problem.empty()) discovery.notes.push_back(usb.problem);
  const size_t listed = paths.size();
  for (size_t i = listed; i < usb.devices.size(); ++i) {
    const UsbDeviceSeen& seen = usb.devices[i];
    FoundDevice device;
    device.kind = DeviceKind::kGen1Hid;
    device.serial = seen.serial;
    device.source = seen.node;
    device.problem =
        !seen.problem.empty()
            ? seen.problem
            : fmt::format("attached at {} but it has no hidraw node: the kernel's HID driver is "
                          "not bound to it (a program using libusb may have detached it; unplug "
                          "and replug the display)",
                          seen.node);
    discovery.devices.push_back(std::move(device));
  }
}

}  // namespace

std::string FoundDevice::kind_name() const {
  return kind == DeviceKind::kGen1Hid ? "Gen1 (USB HID EEPROM)" : "USB volume";
}

std::string FoundDevice::describe() const {
  return fmt::format("{}: {} at {}", serial.empty() ? std::string("(no serial)") : serial,
                     kind_name(), source);
}

Discovery discover_devices(const DiscoveryOptions& options) {
  options.gen1.check();
  Discovery discovery;
  discovery.root = options.root;
  if (options.usb) find_gen1_units(options, discovery);
  for (VolumeCalibration& v : find_volume_calibrations(options.root, options.read_file)) {
    FoundDevice device;
    device.kind = DeviceKind::kUsbVolume;
    device.serial = v.serial;
    device.source = v.file.string();
    device.problem = v.problem;
    device.visual_json = std::move(v.text);
    if (device.readable()) note_panel(device);
    discovery.devices.push_back(std::move(device));
  }
  const std::vector<ConnectedMonitor> monitors = connected_monitors(options.root);
  for (FoundDevice& device : discovery.devices) {
    if (!device.readable()) continue;
    const MonitorMatch match =
        match_monitor(monitors, options.monitor_prefix, device.screen_w, device.screen_h);
    device.monitor = match.monitor;
    device.monitor_problem = match.problem;
  }
  return discovery;
}

std::string nothing_found_message(const Discovery& discovery) {
  const std::string root = discovery.root.empty() || discovery.root == "/"
                               ? std::string()
                               : fmt::format(" under {}", discovery.root.string());
  std::string text = fmt::format(
      "no Looking Glass found: no Gen1 unit on USB HID (04d8:ef7e) and no mounted volume{} with "
      "{}/{}", root, kCalibrationFolder, kCalibrationFile);
  for (const std::string& note : discovery.notes) text += "; " + note;
  text += "; connect the display's USB cable (later units: wait for its volume to be mounted, "
          "or mount it), or pass --calibration with a copy of its visual.json (docs/devices.md)";
  return text;
}

const FoundDevice& select_device(const Discovery& discovery, const std::string& spec) {
  const auto& devices = discovery.devices;
  if (devices.empty()) throw InputError(nothing_found_message(discovery));
  auto list = [&] {
    std::string text;
    for (const FoundDevice& d : devices)
      text += (text.empty() ? "" : "; ") + d.describe() +
              (d.readable() ? std::string() : " (unreadable)");
    return text;
  };
  if (spec.empty() || spec == "auto") {
    std::vector<const FoundDevice*> readable;
    for (const FoundDevice& d : devices)
      if (d.readable()) readable.push_back(&d);
    if (devices.size() == 1 && !devices[0].readable())
      throw_input_error("{}: {}", devices[0].describe(), devices[0].problem);
    if (readable.size() == 1) return *readable[0];
    if (readable.empty())
      throw_input_error("no Looking Glass with a readable calibration: {}; the first: {}", list(),
                        devices[0].problem);
    throw_input_error("{} Looking Glass units found: {}; pass --device SERIAL (or --serial) to "
                      "choose one", readable.size(), list());
  }
  std::vector<const FoundDevice*> named;
  for (const FoundDevice& d : devices)
    if (same_serial(d.serial, spec)) named.push_back(&d);
  if (named.empty())
    throw_input_error("no Looking Glass with serial {}: found {}", spec, list());
  for (const FoundDevice* d : named)
    if (d->readable()) return *d;
  throw_input_error("{}: {}", named[0]->describe(), named[0]->problem);
}

display::Calibration calibration_of(const FoundDevice& device) {
  if (!device.readable()) throw_input_error("{}: {}", device.describe(), device.problem);
  display::Calibration c = display::parse_calibration(device.visual_json, device.source);
  c.provenance["tool"] = "lfd device read";
  c.provenance["method"] = "factory calibration read from the device";
  c.provenance["device"] = {{"serial", device.serial}, {"kind", device.kind_name()},
                            {"source", device.source}};
  return c;
}

display::Calibration read_device_calibration(const std::string& spec, const DiscoveryOptions& options) {
  const Discovery discovery = discover_devices(options);
  return calibration_of(select_device(discovery, spec));
}

}  // namespace lfd::device
