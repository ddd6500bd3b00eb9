#include "util/data_dir.hpp"

#include <cstdlib>
#include <system_error>

// Set by util/CMakeLists.txt for this file only (the build tree's paths stay out of the
// installed libraries' interface):
//   LFD_SOURCE_DATA_DIR      the source tree's data/
//   LFD_DATA_DIR_FROM_BIN    the data folder relative to the installed program ("../share/lfd")
//   LFD_INSTALL_DATA_DIR     the data folder under the configured install prefix

namespace lfd {
namespace {

namespace fs = std::filesystem;

bool is_dir(const fs::path& p) {
  std::error_code ec;
  return fs::is_directory(p, ec);
}

fs::path find_data_dir() {
  if (const char* env = std::getenv("LFD_DATA_DIR"); env && *env) return fs::path(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = (exe.parent_path() / LFD_DATA_DIR_FROM_BIN).lexically_normal();
    if (is_dir(installed)) return installed;
  }
  if (is_dir(LFD_SOURCE_DATA_DIR)) return LFD_SOURCE_DATA_DIR;
  if (is_dir(LFD_INSTALL_DATA_DIR)) return LFD_INSTALL_DATA_DIR;
  return LFD_SOURCE_DATA_DIR;
}

}  // namespace

fs::path data_dir() {
  static const fs::path dir = find_data_dir();
  return dir;
}

}  // namespace lfd
