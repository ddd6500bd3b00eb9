#pragma once
// `lfd serve --status`: asks the running service what it shows, through its own Bridge endpoint
// `lfd_status` (docs/serve.md).
#include <nlohmann/json.hpp>

#include "serve/listen_address.hpp"

namespace lfd::serve {

// The status payload; throws InputError when no service answers at the address.
nlohmann::json query_status(const ListenAddress& address, int timeout_s = 3);

}  // namespace lfd::serve
