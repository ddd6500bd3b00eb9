#pragma once
// The HoloPlay Service commands (docs/serve.md "HoloPlay Service protocol", "Sources"): one
// handler per command, from a parsed request to a reply map; `error` 0 is success, which is
// all holoplay-core looks at (it rejects its promise on anything else).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve/decoded_quilts.hpp"
#include "serve/display_service.hpp"
#include "serve/holoplay_request.hpp"
#include "serve/memory_budget.hpp"
#include "serve/quilt_cache.hpp"
#include "serve/serve_limits.hpp"

namespace lfd::serve {

// The `error` values of a reply.
enum class HoloPlayError : int {
  kNone = 0,
  kBadMessage = 1,      // not CBOR, not the request map, over a limit
  kUnknownCommand = 2,  // a command the service does not know or implement
  kBadArgument = 3,     // a field missing or out of range, an image that does not decode
  kNotFound = 4,        // a cached quilt that is not there
  kInternal = 5,        // the display failed
  kBusy = 6,            // the memory budget or the decoders are in use now: try again (lfd's)
};

inline constexpr const char* kHoloPlayServiceVersion = "1.2.2";  // what `info` reports

class HoloPlayProtocol {
 public:
  HoloPlayProtocol(DisplayService& displays, QuiltCache& cache, DecodedQuilts& decoded, MemoryBudget& budget,
                   const ServeLimits& limits);
  // A reply for any payload; bad input gets an error reply and a log line, never an exception.
  std::vector<std::uint8_t> handle(std::span<const std::uint8_t> payload);
  // The same for a message whose bytes were admitted already (`held`, from admit).
  std::vector<std::uint8_t> handle(std::span<const std::uint8_t> payload, MemoryBudget::Reservation held);
  // Whether the message carries an image to decode (show or cache with `bin`): the content
  // lane's work. A large message always does; a small one is parsed to see (a small PNG still
  // decodes into a large picture). Unparsable messages do not: their error reply is cheap.
  bool carries_content(std::span<const std::uint8_t> payload, std::size_t small_bytes) const;
  // What a message of `bytes` holds while it is handled, if the budget has it now; empty if not.
  MemoryBudget::Reservation admit(std::size_t bytes);
  // Error 6 with `message`: the reply to a request refused before it was read.
  static std::vector<std::uint8_t> busy_reply(const std::string& message);
  nlohmann::json handle_request(const HoloPlayRequest& request);

 private:
  nlohmann::json info() const;
  // Each display's lenticular shader uniforms under HoloPlayCore's property names (docs/serve.md).
  nlohmann::json uniforms() const;
  nlohmann::json show(const HoloPlayRequest& request);
  nlohmann::json cache(const HoloPlayRequest& request);
  nlohmann::json check(const HoloPlayRequest& request) const;
  nlohmann::json erase(const HoloPlayRequest& request);
  nlohmann::json wipe(const HoloPlayRequest& request);
  int target_display(const nlohmann::json& args) const;
  std::string quilt_name(const nlohmann::json& holder) const;

  DisplayService& displays_;
  QuiltCache& cache_;
  DecodedQuilts& decoded_;
  MemoryBudget& budget_;
  const ServeLimits& limits_;
};

nlohmann::json holoplay_error(HoloPlayError error, const std::string& message);

}  // namespace lfd::serve
