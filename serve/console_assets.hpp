#pragma once
// The console page's files (serve/console/page/), embedded into the program at build time by
// embed_assets.cmake, so the page works with no network, no CDN and no node at build time.
#include <string_view>

namespace lfd::serve {

struct ConsoleAsset {
  std::string_view name;          // "index.html", "console.js", ...
  std::string_view content_type;  // "text/html; charset=utf-8", ...
  std::string_view bytes;
};

// The asset called `name`, or nullptr.
const ConsoleAsset* console_asset(std::string_view name);

}  // namespace lfd::serve
