#pragma once
// A `uri` from a request, read only if it names a regular file the user may read, under the
// size limit (docs/serve.md, "Security model"). `file://` URIs (percent-decoded) and absolute
// paths; http(s) and everything else are refused: the service fetches nothing from the network
// for a web page. Nothing is ever written to a path from a request.
#include <cstddef>
#include <filesystem>
#include <string>

namespace lfd::serve {

// The checked path; throws InputError naming the uri and the reason.
std::filesystem::path checked_request_file(const std::string& uri, std::size_t max_bytes);

}  // namespace lfd::serve
