#include "device/usb_enumeration.hpp"

#include <fmt/format.h>
#include <libusb.h>

#include "device/gen1_eeprom.hpp"
#include "device/udev_rules.hpp"

namespace lfd::device {

namespace {

std::string string_descriptor(libusb_device_handle* handle, uint8_t index) {
  if (!handle || index == 0) return {};
  unsigned char text[256] = {};
  const int n = libusb_get_string_descriptor_ascii(handle, index, text, sizeof(text));
  return n > 0 ? std::string(reinterpret_cast<char*>(text), size_t(n)) : std::string();
}

}  // namespace

UsbEnumeration enumerate_usb_looking_glass() {
  UsbEnumeration result;
  libusb_context* context = nullptr;
  if (const int rc = libusb_init(&context); rc != 0) {
    result.problem = fmt::format("libusb cannot enumerate the USB bus ({}): no /dev/bus/usb here?",
                                 libusb_error_name(rc));
    return result;
  }
  libusb_device** list = nullptr;
  const ssize_t count = libusb_get_device_list(context, &list);
  if (count < 0) {
    result.problem = fmt::format("libusb cannot list USB devices ({})", libusb_error_name(int(count)));
    libusb_exit(context);
    return result;
  }
  for (ssize_t i = 0; i < count; ++i) {
    libusb_device* device = list[i];
    libusb_device_descriptor descriptor{};
    if (libusb_get_device_descriptor(device, &descriptor) != 0) continue;
    if (descriptor.idVendor != kGen1VendorId || descriptor.idProduct != kGen1ProductId) continue;
    UsbDeviceSeen seen;
    seen.vendor_id = descriptor.idVendor;
    seen.product_id = descriptor.idProduct;
    seen.bus = libusb_get_bus_number(device);
    seen.address = libusb_get_device_address(device);
    seen.node = fmt::format("/dev/bus/usb/{:03d}/{:03d}", seen.bus, seen.address);
    libusb_device_handle* handle = nullptr;
    const int rc = libusb_open(device, &handle);
    if (rc == 0) {
      seen.product = string_descriptor(handle, descriptor.iProduct);
      seen.serial = string_descriptor(handle, descriptor.iSerialNumber);
      libusb_close(handle);
      // The Microchip ID is shared: a readable product string that is not HoloPlay is not ours.
      if (!seen.product.empty() && seen.product != kGen1Product) continue;
    } else if (rc == LIBUSB_ERROR_ACCESS) {
      seen.problem = fmt::format("permission denied on {}: {}", seen.node, udev_rules_advice());
    } else if (rc == LIBUSB_ERROR_BUSY) {
      seen.problem = fmt::format("{} is busy (another program holds it)", seen.node);
    } else {
      seen.problem = fmt::format("cannot open {}: {}", seen.node, libusb_error_name(rc));
    }
    result.devices.push_back(std::move(seen));
  }
  libusb_free_device_list(list, 1);
  libusb_exit(context);
  return result;
}

}  // namespace lfd::device
