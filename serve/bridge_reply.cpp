// Bridge's reply shape (docs/serve.md).
#include "serve/bridge_reply.hpp"

namespace lfd::serve {

nlohmann::json wrapped(const std::string& name, const std::string& type, nlohmann::json value) {
  return {{"name", name}, {"type", type}, {"value", std::move(value)}};
}

nlohmann::json bridge_reply(const std::string& endpoint, const std::string& orchestration,
                            nlohmann::json payload, const std::string& status) {
  nlohmann::json reply = {{"name", endpoint}};
  if (!orchestration.empty()) reply["orchestration"] = wstring("orchestration", orchestration);
  if (!payload.is_null()) reply["payload"] = std::move(payload);
  reply["status"] = wstring("status", status);
  return reply;
}

nlohmann::json bridge_event(const std::string& event, const std::string& orchestration, nlohmann::json fields) {
  fields["event"] = wstring("event", event);
  return bridge_reply(event, orchestration, wrapped("value", "VARIANT_MAP", std::move(fields)));
}

}  // namespace lfd::serve
