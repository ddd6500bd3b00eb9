#pragma once
// The name the service stores an upload under (docs/console.md, "Uploads"), made from the name
// the client gave, and the check that a request's name is a plain name of the content folder.
// A parser of request input: fuzzed (fuzz_console_request).
#include <string>
#include <string_view>

namespace lfd::serve {

// InputError for '/', '\\', "..", control characters or an empty or over-long (200) name; other
// characters outside [A-Za-z0-9._-] become '_', and a leading '.' too (no hidden files: the
// folder's own uploads in flight are).
std::string library_file_name(std::string_view client_name);

}  // namespace lfd::serve
