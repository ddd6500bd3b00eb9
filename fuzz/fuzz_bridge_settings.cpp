// libFuzzer target: lfd's bridge settings (bridge_inproc/bridge_settings.hpp, what initialize_bridge
// reads) and the C API's strings (bridge_inproc/wide_text.hpp: a char or wchar_t string, bounded).
// Settings must parse or throw lfd::InputError; a string must decode or be refused with BadCall,
// never read past its terminator. Anything else is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bridge_inproc/bridge_log.hpp"
#include "bridge_inproc/bridge_settings.hpp"
#include "bridge_inproc/wide_text.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const lfd::bridge::LfdBridgeSettings s = lfd::bridge::parse_lfd_settings(text, "fuzz");
    for (const std::string& c : s.calibrations) (void)c.size();
  } catch (const lfd::InputError&) {
  }
  // The same bytes as a C string, terminated by four zero bytes (a char or a wchar_t end).
  std::vector<uint8_t> bytes(data, data + size);
  bytes.resize(size + 4 + (4 - size % 4) % 4, 0);
  try {
    const std::string decoded = lfd::bridge::text_of_c_or_wide(bytes.data(), "fuzz");
    if (decoded.empty()) std::abort();  // refused or non-empty, never empty
  } catch (const lfd::bridge::BadCall&) {
  }
  return 0;
}
