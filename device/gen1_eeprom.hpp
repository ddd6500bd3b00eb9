#pragma once
// The Gen1 Looking Glass calibration EEPROM over USB HID (docs/devices.md; after
// lonetech/LookingGlass lgeeprom.py): a feature report [0, 0 (read), page hi, page lo, 64 x 0]
// asks for one 64-byte page; the reply is an input report [buttons, command echo, page hi,
// page lo, 64 bytes]. Page 0 starts with the big-endian length L of the JSON text that follows;
// pages 0 .. ceil((L+4)/64)-1 hold it.
//
// The device sends button reports all the time, so replies are matched on the echoed command and
// page, and everything else is skipped; a 68-byte report may arrive as 64 + 4 bytes and is
// joined; every read has a time-out, every page a deadline (after which it is asked for again),
// and the whole read an overall deadline. Errors are one line naming the device and the page.
#include <chrono>
#include <functional>
#include <string>

#include "device/hid_transport.hpp"

namespace lfd::device {

inline constexpr uint16_t kGen1VendorId = 0x04d8;   // Microchip: check the product string too
inline constexpr uint16_t kGen1ProductId = 0xef7e;
inline constexpr const char* kGen1Product = "HoloPlay";
inline constexpr size_t kEepromPageBytes = 64;
inline constexpr size_t kEepromReportBytes = 68;  // buttons, command, page (2), page data

using Clock = std::function<std::chrono::steady_clock::time_point()>;

struct Gen1ReadOptions {
  std::chrono::milliseconds read_timeout{100};    // one read of one input report
  std::chrono::milliseconds page_timeout{600};    // waiting for one page's reply before asking again
  int requests_per_page = 3;                      // requests for one page before giving up
  std::chrono::milliseconds drain_time{150};      // skipping pending reports before the first request
  std::chrono::milliseconds overall_timeout{15000};
  // A sane bound on the length prefix: a Gen1 visual.json is about 1 KiB; an erased EEPROM
  // reads 0xFFFFFFFF. 16 KiB is 256 pages, well inside the overall deadline.
  size_t max_json_bytes = 16384;
  Clock clock = [] { return std::chrono::steady_clock::now(); };

  void check() const;  // InputError naming the field
};

// What a read saw besides the pages, for messages and tests.
struct Gen1ReadStats {
  int pages = 0;
  int requests = 0;
  int skipped_reports = 0;    // button reports and replies to other pages or commands
  int dropped_fragments = 0;  // partial reports that could not be joined
};

// The calibration JSON text exactly as the EEPROM holds it (bytes [4, 4 + L) of the pages).
// Throws InputError for what the EEPROM holds (erased: L = 0xFFFFFFFF; empty; L beyond
// max_json_bytes; text that is not a visual.json) and DeviceError for the connection (no reply
// within the deadlines, the device gone, a failed request).
std::string read_gen1_calibration(HidTransport& device, const Gen1ReadOptions& options = {},
                                  Gen1ReadStats* stats = nullptr);

// "HoloPlay LKG-2K-04409 (/dev/hidraw3)": how messages name a device.
std::string describe_hid_device(const HidDeviceInfo& info);

}  // namespace lfd::device
