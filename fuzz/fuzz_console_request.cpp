// libFuzzer target: what the console reads from a request (docs/console.md): an upload's or a
// rename's file name (serve::library_file_name) and the Cookie / Authorization headers the access
// token is looked for in (serve::AccessToken::carried_by). A name is made plain or refused with
// lfd::InputError; the token is found only where it is.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "serve/access_token.hpp"
#include "serve/library_file_name.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  try {
    const std::string name = lfd::serve::library_file_name(input);
    if (name.empty() || name.size() > 200 || name.front() == '.' || name.find("..") != std::string::npos) std::abort();
    for (const char c : name)
      if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-'))
        std::abort();
  } catch (const lfd::InputError&) {
  }
  // The first half as the Cookie header, the rest as Authorization.
  static const lfd::serve::AccessToken token(std::string(64, 'a'));
  const std::string_view cookie = input.substr(0, size / 2), authorization = input.substr(size / 2);
  if (token.carried_by(cookie, authorization) && input.find(token.text()) == std::string_view::npos) std::abort();
  return 0;
}
