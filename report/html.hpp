#pragma once
// Small helpers shared by the HTML reports (validation, demo, calibration): the pages are
// written by hand as self-contained files, so text from users (file and folder names,
// messages) must be escaped.
#include <string>

namespace lfd::report {

// Escapes text for HTML element content and double-quoted attribute values.
inline std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace lfd::report
