#pragma once
// A device that stopped answering, went away or cannot be opened: a failure of the device or of
// its connection (exit code 1), as opposed to lfd::InputError for what it holds (an erased
// EEPROM, a visual.json that does not parse: exit code 2).
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace lfd::device {

class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

template <typename... Args>
[[noreturn]] void throw_device_error(fmt::format_string<Args...> f, Args&&... args) {
  throw DeviceError(fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace lfd::device
