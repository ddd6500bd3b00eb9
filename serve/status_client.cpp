// Asking a running lfd serve what it shows (docs/serve.md).
#include "serve/status_client.hpp"

#include <httplib.h>

#include "util/error.hpp"

namespace lfd::serve {

nlohmann::json query_status(const ListenAddress& address, int timeout_s) {
  httplib::Client client(address.host, address.bridge_port);
  client.set_connection_timeout(timeout_s, 0);
  client.set_read_timeout(timeout_s, 0);
  const auto result = client.Put("/lfd_status", "{}", "application/json");
  if (!result)
    throw_input_error("no lfd serve answers at http://{}:{}/ ({})", address.url_host(), address.bridge_port,
                      httplib::to_string(result.error()));
  const auto body = nlohmann::json::parse(result->body, nullptr, false);
  if (result->status != 200 || body.is_discarded() || !body.contains("payload"))
    throw_input_error("http://{}:{}/lfd_status: not lfd serve's answer (HTTP {})", address.url_host(),
                      address.bridge_port, result->status);
  return body["payload"]["value"];
}

}  // namespace lfd::serve
