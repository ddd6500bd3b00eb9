#pragma once
// A fake Gen1 Looking Glass behind the HidTransport interface: it serves EEPROM pages built from
// a visual.json (big-endian length, the text, 0xFF to the end of the EEPROM), answers each page
// request with an input report [buttons, 0, page hi, page lo, 64 bytes], and injects the faults
// real units and backends show. Time is a fake clock that reads advance, so time-outs cost no
// real time and every test returns at once.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "device/device_error.hpp"
#include "device/gen1_eeprom.hpp"
#include "device/hid_transport.hpp"

namespace lfd::test {

struct FakeClock {
  std::chrono::steady_clock::time_point now{};
  device::Clock fn() {
    return [this] { return now; };
  }
};

// The EEPROM image of a calibration text: [L big-endian][text], padded with 0xFF to `bytes`.
inline std::vector<uint8_t> eeprom_image(const std::string& text, size_t bytes = 4096,
                                         uint32_t length_prefix = 0, bool use_prefix = false) {
  const uint32_t length = use_prefix ? length_prefix : uint32_t(text.size());
  std::vector<uint8_t> image(std::max(bytes, text.size() + 4), 0xff);
  for (int i = 0; i < 4; ++i) image[size_t(i)] = uint8_t(length >> (24 - 8 * i));
  std::copy(text.begin(), text.end(), image.begin() + 4);
  return image;
}

class FakeHoloPlay : public device::HidTransport {
 public:
  // Faults, all off by default.
  int stale_reports_before_reply = 0;  // button reports queued ahead of every reply
  int pending_at_open = 0;             // button reports waiting before the first request
  bool split_replies = false;          // each reply arrives as 64 + 4 bytes
  bool wrong_page_first = false;       // a reply for another page, then the right one
  bool wrong_command_first = false;    // an echo of another command, then the right reply
  int truncate_first_replies = 0;      // the first N replies lose their last bytes, rest never comes
  int ignore_first_requests = 0;       // the first N requests get no reply (lost)
  int disconnect_at_page = -1;         // reading throws once this page was asked for
  bool never_reply = false;            // requests are accepted but never answered
  bool endless_buttons = false;        // a button report whenever nothing else is queued
  bool send_fails = false;             // the feature report is refused
  std::chrono::milliseconds per_report{1};  // fake time each delivered report takes

  FakeHoloPlay(std::vector<uint8_t> eeprom, FakeClock& clock) : eeprom_(std::move(eeprom)), clock_(clock) {
    info_.path = "/dev/hidraw-fake";
    info_.product = device::kGen1Product;
    info_.serial = "FAKE0001";
    info_.vendor_id = device::kGen1VendorId;
    info_.product_id = device::kGen1ProductId;
  }

  const device::HidDeviceInfo& info() const override { return info_; }
  int requests = 0;

  void send_feature_report(std::span<const uint8_t> bytes) override {
    if (send_fails) throw device::DeviceError("the feature report was refused (EPIPE)");
    if (bytes.size() != device::kEepromReportBytes || bytes[0] != 0 || bytes[1] != 0)
      throw device::DeviceError("malformed request");
    for (size_t i = 4; i < bytes.size(); ++i)
      if (bytes[i] != 0) throw device::DeviceError("malformed request padding");
    const int page = bytes[2] << 8 | bytes[3];
    ++requests;
    if (page == disconnect_at_page) disconnected_ = true;
    if (never_reply || requests <= ignore_first_requests) return;
    for (int i = 0; i < stale_reports_before_reply; ++i) queue_.push_back(button_report());
    if (wrong_page_first) queue_.push_back(reply(page + 1));
    if (wrong_command_first) {
      auto r = reply(page);
      r[1] = 1;
      queue_.push_back(r);
    }
    auto r = reply(page);
    if (truncate_first_replies > 0) {
      --truncate_first_replies;
      r.resize(40);
      queue_.push_back(r);
      return;
    }
    if (split_replies) {
      queue_.push_back(std::vector<uint8_t>(r.begin(), r.begin() + 64));
      queue_.push_back(std::vector<uint8_t>(r.begin() + 64, r.end()));
    } else {
      queue_.push_back(r);
    }
  }

  size_t read(std::span<uint8_t> buffer, std::chrono::milliseconds timeout) override {
    if (disconnected_) throw device::DeviceError("reading failed, the device is gone (ENODEV)");
    if (pending_at_open > 0) {
      --pending_at_open;
      return deliver(button_report(), buffer);
    }
    if (queue_.empty()) {
      if (endless_buttons) return deliver(button_report(), buffer);
      clock_.now += timeout;
      return 0;
    }
    auto report = queue_.front();
    queue_.pop_front();
    return deliver(report, buffer);
  }

 private:
  std::vector<uint8_t> button_report() const {
    std::vector<uint8_t> r(device::kEepromReportBytes, 0);
    r[0] = 0x01;  // a button held; the rest looks like a reply to page 0 of command 0xff
    r[1] = 0xff;
    return r;
  }
  std::vector<uint8_t> reply(int page) const {
    std::vector<uint8_t> r(device::kEepromReportBytes, 0xff);
    r[0] = 0;
    r[1] = 0;
    r[2] = uint8_t(page >> 8);
    r[3] = uint8_t(page & 0xff);
    const size_t start = size_t(page) * device::kEepromPageBytes;
    for (size_t i = 0; i < device::kEepromPageBytes && start + i < eeprom_.size(); ++i)
      r[4 + i] = eeprom_[start + i];
    return r;
  }
  size_t deliver(const std::vector<uint8_t>& report, std::span<uint8_t> buffer) {
    clock_.now += per_report;
    const size_t n = std::min(report.size(), buffer.size());
    std::copy(report.begin(), report.begin() + long(n), buffer.begin());
    return n;
  }

  std::vector<uint8_t> eeprom_;
  FakeClock& clock_;
  device::HidDeviceInfo info_;
  std::deque<std::vector<uint8_t>> queue_;
  bool disconnected_ = false;
};

}  // namespace lfd::test
