#pragma once
// Error types shared by every module. The program maps them to exit codes:
// InputError -> 2 (bad usage or bad input: a file or field is named in the message),
// anything else -> 1.
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace lfd {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws InputError with a formatted one-line message.
template <typename... Args>
[[noreturn]] void throw_input_error(fmt::format_string<Args...> f, Args&&... args) {
  throw InputError(fmt::format(f, std::forward<Args>(args)...));
}

// Throws InputError("<file>: <field>: <message>") unless `ok`.
void require_field(bool ok, const std::string& file, const std::string& field,
                   const std::string& message);

}  // namespace lfd
