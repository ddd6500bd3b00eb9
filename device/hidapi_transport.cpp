#include "device/hidapi_transport.hpp"

#include <cerrno>
#include <cstring>
#include <cwchar>
#include <unistd.h>

#include <hidapi/hidapi.h>

#include "device/device_error.hpp"
#include "device/udev_rules.hpp"

namespace lfd::device {

namespace {

std::string narrow(const wchar_t* text) {
  if (!text) return {};
  std::string out;
  for (; *text; ++text) out += (*text >= 32 && *text < 127) ? char(*text) : '?';
  return out;
}

bool hidapi_ready() {
  static const bool ready = hid_init() == 0;
  return ready;
}

class HidapiTransport : public HidTransport {
 public:
  HidapiTransport(hid_device* handle, HidDeviceInfo info) : handle_(handle), info_(std::move(info)) {}
  ~HidapiTransport() override { hid_close(handle_); }
  const HidDeviceInfo& info() const override { return info_; }

  void send_feature_report(std::span<const uint8_t> bytes) override {
    if (hid_send_feature_report(handle_, bytes.data(), bytes.size()) < 0)
      throw_device_error("sending a feature report failed: {}", error());
  }

  size_t read(std::span<uint8_t> buffer, std::chrono::milliseconds timeout) override {
    const int n = hid_read_timeout(handle_, buffer.data(), buffer.size(), int(timeout.count()));
    if (n < 0) throw_device_error("reading failed, the device is gone or stopped answering: {}", error());
    return size_t(n);
  }

 private:
  std::string error() const {
    const std::string text = narrow(hid_error(handle_));
    return text.empty() ? std::string("unknown error") : text;
  }
  hid_device* handle_;
  HidDeviceInfo info_;
};

}  // namespace

std::vector<HidDeviceInfo> enumerate_hid(uint16_t vendor_id, uint16_t product_id) {
  std::vector<HidDeviceInfo> found;
  if (!hidapi_ready()) return found;
  hid_device_info* list = hid_enumerate(vendor_id, product_id);
  for (hid_device_info* d = list; d; d = d->next) {
    HidDeviceInfo info;
    info.path = d->path ? d->path : "";
    info.serial = narrow(d->serial_number);
    info.product = narrow(d->product_string);
    info.vendor_id = d->vendor_id;
    info.product_id = d->product_id;
    info.interface_number = d->interface_number;
    found.push_back(std::move(info));
  }
  hid_free_enumeration(list);
  return found;
}

std::unique_ptr<HidTransport> open_hid(const HidDeviceInfo& info) {
  const std::string name = info.product.empty() ? info.path : info.product + " (" + info.path + ")";
  if (!hidapi_ready()) throw_device_error("{}: hidapi could not start (no hidraw support?)", name);
  // access() tells the reason hidapi does not: the node's permissions.
  if (::access(info.path.c_str(), F_OK) != 0)
    throw_device_error("{}: the node {} does not exist (unplugged?)", name, info.path);
  if (::access(info.path.c_str(), R_OK | W_OK) != 0 && errno == EACCES)
    throw_device_error("{}: permission denied on {}: {}", name, info.path, udev_rules_advice());
  errno = 0;
  hid_device* handle = hid_open_path(info.path.c_str());
  if (!handle) {
    const int err = errno;
    if (err == EACCES || err == EPERM)
      throw_device_error("{}: permission denied on {}: {}", name, info.path, udev_rules_advice());
    if (err == EBUSY)
      throw_device_error("{}: {} is busy: another program holds it (HoloPlay Service?); close it "
                         "and try again", name, info.path);
    throw_device_error("{}: cannot open {}: {}", name, info.path,
                       err ? std::strerror(err) : "hidapi could not open it");
  }
  return std::make_unique<HidapiTransport>(handle, info);
}

}  // namespace lfd::device
