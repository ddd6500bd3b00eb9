#pragma once
// The program's version: the project version (CMakeLists.txt), the git commit the build comes
// from ("abc1234", "abc1234-dirty" for uncommitted changes, "unknown" outside a git checkout)
// and the build date. cmake/version_info.cmake reads them at build time.
#include <string>

namespace lfd {

struct VersionInfo {
  std::string version;     // "0.1.0"
  std::string commit;      // "abc1234", "abc1234-dirty" or "unknown"
  std::string build_date;  // "2026-11-22" (UTC)
};

const VersionInfo& version_info();

// "lfd 0.1.0 (commit abc1234, built 2026-11-22)": what `lfd --version` prints.
std::string version_line();

}  // namespace lfd
