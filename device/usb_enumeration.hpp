#pragma once
// libusb's view of the bus: which Looking Glass units are attached, whether their USB device
// node can be opened, and why not (permissions, busy). Used to explain a Gen1 unit that hidapi
// cannot read (no hidraw node, permissions) and to list what is plugged in.
#include <cstdint>
#include <string>
#include <vector>

namespace lfd::device {

struct UsbDeviceSeen {
  uint16_t vendor_id = 0, product_id = 0;
  int bus = 0, address = 0;
  std::string node;     // /dev/bus/usb/BBB/DDD
  std::string product;  // USB product string when the device could be opened
  std::string serial;
  std::string problem;  // why the device node cannot be opened; empty when it can
};

struct UsbEnumeration {
  std::vector<UsbDeviceSeen> devices;
  std::string problem;  // why the bus cannot be enumerated (no usbfs in a container); empty if it can
};

// Attached USB devices with the Gen1 IDs (04d8:ef7e, product "HoloPlay" where readable).
// Never throws.
UsbEnumeration enumerate_usb_looking_glass();

}  // namespace lfd::device
