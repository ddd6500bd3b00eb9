#pragma once
// Every Looking Glass this machine can see, and its factory calibration: Gen1 units over USB HID
// (the EEPROM, gen1_eeprom.hpp), later units on their USB volume (volume_discovery.hpp); libusb
// explains a unit that is attached but cannot be read; DRM EDIDs give each unit's monitor.
// All device access goes through the injectable functions of DiscoveryOptions, so tests run the
// whole discovery on fakes and directory trees.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "device/drm_monitors.hpp"
#include "device/gen1_eeprom.hpp"
#include "device/hid_transport.hpp"
#include "device/usb_enumeration.hpp"
#include "device/volume_discovery.hpp"
#include "display/calibration_file.hpp"

namespace lfd::device {

enum class DeviceKind { kGen1Hid, kUsbVolume };

struct FoundDevice {
  DeviceKind kind = DeviceKind::kUsbVolume;
  std::string serial;       // the calibration's serial; else the USB serial or volume name
  std::string source;       // the EEPROM's node (/dev/hidraw3) or the visual.json path
  std::string visual_json;  // the calibration exactly as the device holds it; empty with a problem
  std::string problem;      // why its calibration cannot be read; empty when it can
  int screen_w = 0, screen_h = 0;
  std::string monitor;          // "DP-1 \"LKG01Do12HjQE\" 1536x2048" when one matches
  std::string monitor_problem;  // why none does

  bool readable() const { return problem.empty(); }
  std::string kind_name() const;  // "Gen1 (USB HID EEPROM)", "USB volume"
  std::string describe() const;   // "LKG-2K-04409: Gen1 (USB HID EEPROM) at /dev/hidraw3"
};

struct DiscoveryOptions {
  std::filesystem::path root = "/";  // every path search starts here
  bool usb = true;                   // look on USB (HID and libusb) besides volumes
  std::string monitor_prefix = "LKG";
  Gen1ReadOptions gen1;
  // Device access; the defaults are hidapi, libusb and the file system.
  std::function<std::vector<HidDeviceInfo>()> enumerate_hid;
  std::function<std::unique_ptr<HidTransport>(const HidDeviceInfo&)> open_hid;
  std::function<UsbEnumeration()> enumerate_usb;
  FileReader read_file = read_whole_file;
};

struct Discovery {
  std::vector<FoundDevice> devices;  // Gen1 units first, then volumes by path
  std::vector<std::string> notes;    // what could not be searched, and why
  std::filesystem::path root;
};

Discovery discover_devices(const DiscoveryOptions& options = {});

// "no Looking Glass found ... ; connect one ... or pass --calibration": what was searched and
// what to do next, one line.
std::string nothing_found_message(const Discovery& discovery);

// The device `spec` names: "auto" (the only one found; when several are, the only readable one)
// or a serial (case-insensitive; a unit's calibration serial, USB serial or volume name).
// Throws InputError naming what was found and what to pass instead; for a device found but
// unreadable, the reason.
const FoundDevice& select_device(const Discovery& discovery, const std::string& spec);

// The calibration of a readable device, with provenance (the device, where it was read).
display::Calibration calibration_of(const FoundDevice& device);

// discover_devices + select_device + calibration_of.
display::Calibration read_device_calibration(const std::string& spec,
                                           const DiscoveryOptions& options = {});

}  // namespace lfd::device
