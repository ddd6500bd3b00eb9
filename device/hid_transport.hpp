#pragma once
// The one door to a HID device. The Gen1 EEPROM reader speaks its protocol through this
// interface only; hidapi_transport.hpp implements it on hidapi (hidraw backend) and the tests on
// a fake that serves EEPROM pages and injects faults.
#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace lfd::device {

// What the system tells about a HID device before it is opened.
struct HidDeviceInfo {
  std::string path;     // the node to open, e.g. /dev/hidraw3
  std::string serial;   // USB serial number string (may be empty)
  std::string product;  // USB product string, "HoloPlay" on Gen1 units
  uint16_t vendor_id = 0, product_id = 0;
  int interface_number = -1;
};

class HidTransport {
 public:
  virtual ~HidTransport() = default;  // closes the device
  virtual const HidDeviceInfo& info() const = 0;
  // Sends a feature report; bytes[0] is the report ID. Throws DeviceError when it fails.
  virtual void send_feature_report(std::span<const uint8_t> bytes) = 0;
  // Reads one input report into `buffer` and returns its length, or 0 when none arrived within
  // `timeout`. Throws DeviceError when the device is gone.
  virtual size_t read(std::span<uint8_t> buffer, std::chrono::milliseconds timeout) = 0;
};

}  // namespace lfd::device
