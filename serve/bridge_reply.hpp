#pragma once
// Bridge's reply shape (docs/serve.md "Sources"): every value wrapped
// `{name, type, value}` with Bridge's type names (WSTRING, UNSIGNED_INT, INT, FLOAT, INT2,
// VARIANT_MAP), and `status.value` one of "Completion", "Pending", "Failure",
// "UnknownOrchestration" (bridge.js's schemas, src/schemas).
#include <string>

#include <nlohmann/json.hpp>

namespace lfd::serve {

nlohmann::json wrapped(const std::string& name, const std::string& type, nlohmann::json value);
inline nlohmann::json wstring(const std::string& name, const std::string& value) {
  return wrapped(name, "WSTRING", value);
}

// `{name: endpoint, orchestration?, payload?, status}`; `payload` null leaves it out.
nlohmann::json bridge_reply(const std::string& endpoint, const std::string& orchestration,
                            nlohmann::json payload, const std::string& status = "Completion");

// An event on the event socket: `payload.value.event.value` is the event's name (what
// bridge.js dispatches on), with `fields` (already wrapped) beside it.
nlohmann::json bridge_event(const std::string& event, const std::string& orchestration,
                            nlohmann::json fields = nlohmann::json::object());

}  // namespace lfd::serve
