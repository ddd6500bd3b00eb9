// A client's file name made into a name of the content folder (docs/console.md, "Uploads").
#include "serve/library_file_name.hpp"

#include "util/error.hpp"

namespace lfd::serve {

namespace {
constexpr std::size_t kMaxNameChars = 200;
}  // namespace

std::string library_file_name(std::string_view client_name) {
  if (client_name.empty()) throw_input_error("name: empty");
  if (client_name.size() > kMaxNameChars) throw_input_error("name: longer than {} characters", kMaxNameChars);
  for (const char c : client_name)  // before the name is echoed in a message
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) throw_input_error("name: a control character");
  if (client_name.find("..") != std::string_view::npos || client_name.find('/') != std::string_view::npos ||
      client_name.find('\\') != std::string_view::npos)
    throw_input_error("name {}: not a plain file name ('/', '\\' and '..' are refused)", client_name);
  std::string out;
  for (const char c : client_name) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                       c == '_' || c == '-';
    out += plain ? c : '_';
  }
  if (out.front() == '.') out.front() = '_';  // no hidden files: the folder's own are
  return out;
}

}  // namespace lfd::serve
