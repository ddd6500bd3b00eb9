#pragma once
// The library's log (docs/bridge-inproc.md "Bad calls"): one line per refused call, on stderr and
// appended to the file named by LFD_BRIDGE_LOG when it is set. A client of the vendor's library
// sees false; the line says which call and why.
#include <stdexcept>
#include <string>

namespace lfd::bridge {

// A call the library refuses (unknown window, texture 0, zero sizes, ...): false to the client.
class BadCall : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void refuse(const std::string& reason);

// "bridge_inproc: <call>: <reason>" on stderr and in LFD_BRIDGE_LOG. Thread-safe.
void log_line(const std::string& call, const std::string& reason);
// The same line in LFD_BRIDGE_LOG only: what the library did that a client need not see on its
// stderr (which GL a window's context speaks). Thread-safe.
void log_detail(const std::string& call, const std::string& text);

}  // namespace lfd::bridge
