// Checking a request's `uri` (docs/serve.md, "Security model").
#include "serve/request_file.hpp"

#include <unistd.h>

#include <system_error>

#include "util/error.hpp"

namespace lfd::serve {

namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::string percent_decoded(const std::string& s, const std::string& uri) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '%') {
      out += s[i];
      continue;
    }
    const int hi = i + 2 < s.size() ? hex_digit(s[i + 1]) : -1;
    const int lo = i + 2 < s.size() ? hex_digit(s[i + 2]) : -1;
    if (hi < 0 || lo < 0) throw_input_error("uri {}: a bad percent escape", uri);
    out += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  if (out.find('\0') != std::string::npos) throw_input_error("uri {}: a NUL byte", uri);
  return out;
}

}  // namespace

std::filesystem::path checked_request_file(const std::string& uri, std::size_t max_bytes) {
  std::string path;
  if (uri.rfind("file://", 0) == 0) {
    std::string rest = uri.substr(7);
    if (rest.rfind("localhost/", 0) == 0) rest = rest.substr(9);
    path = percent_decoded(rest, uri);
  } else if (!uri.empty() && uri[0] == '/') {
    path = uri;
    if (path.find('\0') != std::string::npos) throw_input_error("uri: a NUL byte");
  } else {
    throw_input_error("uri {}: only local files (file:// or an absolute path) are read", uri.substr(0, 200));
  }
  if (path.empty() || path[0] != '/') throw_input_error("uri {}: not an absolute path", uri.substr(0, 200));
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::is_regular_file(status))
    throw_input_error("uri {}: not a regular file", uri.substr(0, 200));
  if (::access(path.c_str(), R_OK) != 0) throw_input_error("uri {}: not readable", uri.substr(0, 200));
  const auto size = std::filesystem::file_size(path, ec);
  // Empty files are refused too: /proc and /sys show their files as empty regular ones.
  if (!ec && size == 0) throw_input_error("uri {}: an empty file", uri.substr(0, 200));
  if (ec || size > max_bytes)
    throw_input_error("uri {}: larger than the limit of {} bytes", uri.substr(0, 200), max_bytes);
  return path;
}

}  // namespace lfd::serve
