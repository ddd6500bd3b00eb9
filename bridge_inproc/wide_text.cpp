#include "bridge_inproc/wide_text.hpp"

#include <cstdint>
#include <algorithm>
#include <cstring>

#include "bridge_inproc/bridge_log.hpp"

namespace lfd::bridge {

namespace {
constexpr size_t kMaxChars = 4096;
}

std::string text_of_c_or_wide(const void* p, const std::string& what) {
  if (!p) refuse(what + ": null");
  const auto* bytes = static_cast<const unsigned char*>(p);
  if (bytes[0] == 0) refuse(what + ": empty");
  std::string out;
  if (bytes[1] == 0 && bytes[2] == 0 && bytes[3] == 0) {
    const auto* wide = static_cast<const wchar_t*>(p);
    for (size_t i = 0; wide[i] != 0; ++i) {
      if (i >= kMaxChars) refuse(what + ": longer than 4096 characters");
      const auto c = static_cast<uint32_t>(wide[i]);
      // UTF-8 of the code point.
      if (c < 0x80) {
        out += char(c);
      } else if (c < 0x800) {
        out += char(0xC0 | (c >> 6));
        out += char(0x80 | (c & 0x3F));
      } else if (c < 0x10000) {
        out += char(0xE0 | (c >> 12));
        out += char(0x80 | ((c >> 6) & 0x3F));
        out += char(0x80 | (c & 0x3F));
      } else {
        out += char(0xF0 | (c >> 18));
        out += char(0x80 | ((c >> 12) & 0x3F));
        out += char(0x80 | ((c >> 6) & 0x3F));
        out += char(0x80 | (c & 0x3F));
      }
    }
    return out;
  }
  const size_t n = strnlen(reinterpret_cast<const char*>(bytes), kMaxChars + 1);
  if (n > kMaxChars) refuse(what + ": longer than 4096 characters");
  return std::string(reinterpret_cast<const char*>(bytes), n);
}

std::wstring widen(const std::string& text) {
  std::wstring out;
  for (unsigned char c : text) out += wchar_t(c);
  return out;
}

void write_wide(const std::string& text, int* count, wchar_t* out) {
  if (!count) refuse("the count pointer is null");
  const std::wstring wide = widen(text);
  const int needed = int(wide.size()) + 1;
  if (!out) {
    *count = needed;
    return;
  }
  if (*count <= 0) refuse("the buffer holds " + std::to_string(*count) + " characters");
  const int n = std::min(*count - 1, int(wide.size()));
  std::memcpy(out, wide.data(), size_t(n) * sizeof(wchar_t));
  out[n] = 0;
  *count = n + 1;
}

}  // namespace lfd::bridge
