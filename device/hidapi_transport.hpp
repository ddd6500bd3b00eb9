#pragma once
// HidTransport on hidapi's hidraw backend (docs/devices.md "Sources": the libusb
// backend detaches the kernel HID driver, the hidraw one does not).
#include <memory>
#include <vector>

#include "device/hid_transport.hpp"

namespace lfd::device {

// Every HID device with this vendor and product ID (0, 0: all). Empty when hidapi finds none or
// cannot start (no hidraw support): enumeration never throws.
std::vector<HidDeviceInfo> enumerate_hid(uint16_t vendor_id, uint16_t product_id);

// Opens `info.path`. Throws DeviceError saying why it cannot: the node missing, permission
// denied (naming the node and the command that installs the udev rules), busy.
std::unique_ptr<HidTransport> open_hid(const HidDeviceInfo& info);

}  // namespace lfd::device
