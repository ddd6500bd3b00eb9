#pragma once
// A PUT or POST body read through cpp-httplib's ContentReader with a bound of its own
// (docs/console.md, "Uploads"): the server's payload limit is the console's upload limit, so
// every other route keeps at most its own bound in memory and reads the rest off the connection
// and drops it (bytes left unread would be taken for the next request of a kept-alive
// connection). nullopt when the body was larger than `max_bytes` or cpp-httplib's limit.
#include <cstddef>
#include <optional>
#include <string>

#include <httplib.h>

namespace lfd::serve {

inline std::optional<std::string> read_bounded_body(const httplib::ContentReader& read, std::size_t max_bytes) {
  std::string body;
  bool over = false;
  // false: cpp-httplib refused it first (over its payload limit: read off and dropped).
  const bool whole = read([&](const char* data, std::size_t n) {
    over = over || body.size() + n > max_bytes;
    if (!over) body.append(data, n);
    return true;
  });
  if (over || !whole) return std::nullopt;
  return body;
}

}  // namespace lfd::serve
