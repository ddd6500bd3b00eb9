#include "device/gen1_eeprom.hpp"

#include <array>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "device/device_error.hpp"
#include "display/visual_json.hpp"
#include "util/error.hpp"

namespace lfd::device {

namespace {

using std::chrono::milliseconds;
using Time = std::chrono::steady_clock::time_point;

long long ms(std::chrono::steady_clock::duration d) {
  return std::chrono::duration_cast<milliseconds>(d).count();
}

// One read session: the transport, the deadlines and what was seen.
class Gen1Reader {
 public:
  Gen1Reader(HidTransport& device, const Gen1ReadOptions& options, Gen1ReadStats& stats)
      : device_(device), options_(options), stats_(stats), name_(describe_hid_device(device.info())),
        deadline_(options.clock() + options.overall_timeout) {}

  // Skips the button reports queued before our first request, for at most drain_time.
  void drain() {
    const Time until = options_.clock() + options_.drain_time;
    std::array<uint8_t, 256> buffer{};
    while (options_.clock() < until) {
      const size_t n = read_once(buffer, std::min(options_.read_timeout, milliseconds(10)));
      if (n == 0) break;
      ++stats_.skipped_reports;
    }
  }

  // The 64 data bytes of `page`, asking up to requests_per_page times.
  std::array<uint8_t, kEepromPageBytes> read_page(uint16_t page, int page_count) {
    for (int attempt = 0; attempt < options_.requests_per_page; ++attempt) {
      check_overall(page, page_count);
      request(page);
      if (auto data = await_reply(page, page_count)) {
        ++stats_.pages;
        return *data;
      }
    }
    throw_device_error(
        "{}: no reply to the request for EEPROM page {} within {} ms, asked {} times ({} other "
        "reports skipped, {} partial reports dropped); unplug and replug the display, and close "
        "other programs using it (HoloPlay Service)",
        name_, page, ms(options_.page_timeout), options_.requests_per_page,
        stats_.skipped_reports, stats_.dropped_fragments);
  }

  const std::string& name() const { return name_; }

 private:
  void check_overall(uint16_t page, int page_count) const {
    if (options_.clock() < deadline_) return;
    throw_device_error("{}: gave up after {} ms at EEPROM page {}{} ({} pages read, {} other "
                       "reports skipped)",
                       name_, ms(options_.overall_timeout), page,
                       page_count > 0 ? fmt::format(" of {}", page_count) : std::string(),
                       stats_.pages, stats_.skipped_reports);
  }

  void request(uint16_t page) {
    std::array<uint8_t, kEepromReportBytes> report{};  // report ID 0, command 0 (read), page
    report[2] = uint8_t(page >> 8);
    report[3] = uint8_t(page & 0xff);
    ++stats_.requests;
    try {
      device_.send_feature_report(report);
    } catch (const DeviceError& e) {
      throw_device_error("{}: the request for EEPROM page {} failed: {}", name_, page, e.what());
    }
  }

  size_t read_once(std::span<uint8_t> buffer, milliseconds timeout) {
    try {
      return device_.read(buffer, timeout);
    } catch (const DeviceError& e) {
      throw_device_error("{}: {}", name_, e.what());
    }
  }

  // Reads reports until the reply to `page` comes (its data), or the page deadline passes.
  // Whole reports are read whole; shorter reads are joined until they make one report (64 + 4).
  std::optional<std::array<uint8_t, kEepromPageBytes>> await_reply(uint16_t page, int page_count) {
    const Time until = std::min(options_.clock() + options_.page_timeout, deadline_);
    std::vector<uint8_t> pending;
    std::array<uint8_t, 256> buffer{};
    for (Time now = options_.clock(); now < until; now = options_.clock()) {
      const auto left = std::chrono::duration_cast<milliseconds>(until - now);
      const size_t n = read_once(buffer, std::max(milliseconds(1), std::min(options_.read_timeout, left)));
      std::span<const uint8_t> report;
      if (n == 0) {
        if (!pending.empty()) ++stats_.dropped_fragments;  // its rest never came
        pending.clear();
        continue;
      }
      if (n >= kEepromReportBytes) {
        if (!pending.empty()) ++stats_.dropped_fragments;
        pending.clear();
        report = std::span<const uint8_t>(buffer.data(), kEepromReportBytes);
      } else {
        pending.insert(pending.end(), buffer.begin(), buffer.begin() + long(n));
        if (pending.size() < kEepromReportBytes) continue;
        if (pending.size() > kEepromReportBytes) {  // pieces of different reports
          ++stats_.dropped_fragments;
          pending.clear();
          continue;
        }
        report = pending;
      }
      const bool reply = report[1] == 0 && report[2] == uint8_t(page >> 8) &&
                         report[3] == uint8_t(page & 0xff);
      if (reply) {
        std::array<uint8_t, kEepromPageBytes> data{};
        std::copy(report.begin() + 4, report.begin() + 4 + long(kEepromPageBytes), data.begin());
        return data;
      }
      ++stats_.skipped_reports;  // a button report, or the reply to another request
      pending.clear();
    }
    return std::nullopt;
  }

  HidTransport& device_;
  const Gen1ReadOptions& options_;
  Gen1ReadStats& stats_;
  std::string name_;
  Time deadline_;
};

}  // namespace

void Gen1ReadOptions::check() const {
  if (read_timeout.count() <= 0) throw_input_error("read_timeout must be positive");
  if (page_timeout < read_timeout) throw_input_error("page_timeout must be at least read_timeout");
  if (requests_per_page < 1) throw_input_error("requests_per_page must be at least 1");
  if (overall_timeout < page_timeout) throw_input_error("overall_timeout must be at least page_timeout");
  if (max_json_bytes < 2 || max_json_bytes > (size_t(1) << 24))
    throw_input_error("max_json_bytes must lie in [2, 16 MiB]");
  if (!clock) throw_input_error("clock must be set");
}

std::string describe_hid_device(const HidDeviceInfo& info) {
  std::string text = info.product.empty() ? std::string("HID device") : info.product;
  if (!info.serial.empty()) text += " " + info.serial;
  if (!info.path.empty()) text += " (" + info.path + ")";
  return text;
}

std::string read_gen1_calibration(HidTransport& device, const Gen1ReadOptions& options,
                                  Gen1ReadStats* stats_out) {
  options.check();
  Gen1ReadStats stats;
  Gen1Reader reader(device, options, stats);
  reader.drain();
  const auto first = reader.read_page(0, 0);
  const uint32_t length = uint32_t(first[0]) << 24 | uint32_t(first[1]) << 16 |
                          uint32_t(first[2]) << 8 | uint32_t(first[3]);
  if (length == 0xFFFFFFFFu)
    throw_input_error("{}: the calibration EEPROM is erased (length 0xFFFFFFFF): this unit holds "
                      "no factory calibration; use a copy of its visual.json (--calibration)",
                      reader.name());
  if (length == 0)
    throw_input_error("{}: the calibration EEPROM holds an empty calibration (length 0)",
                      reader.name());
  if (length > options.max_json_bytes)
    throw_input_error("{}: the calibration EEPROM's length prefix says {} bytes, more than a "
                      "calibration can be ({} bytes): the EEPROM is damaged or not a calibration",
                      reader.name(), length, options.max_json_bytes);
  const int page_count = int((length + 4 + kEepromPageBytes - 1) / kEepromPageBytes);
  std::string bytes(first.begin(), first.end());
  for (int page = 1; page < page_count; ++page) {
    const auto data = reader.read_page(uint16_t(page), page_count);
    bytes.append(data.begin(), data.end());
  }
  if (stats_out) *stats_out = stats;
  std::string text = bytes.substr(4, length);
  // What the EEPROM holds must be a calibration; the parser's message names the field.
  const std::string where = reader.name() + ": EEPROM calibration";
  display::parse_visual_json(text, where).check(where);
  return text;
}

}  // namespace lfd::device
