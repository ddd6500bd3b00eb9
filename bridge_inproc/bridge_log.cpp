#include "bridge_inproc/bridge_log.hpp"

#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace lfd::bridge {

void refuse(const std::string& reason) { throw BadCall(reason); }

void log_line(const std::string& call, const std::string& reason) {
  static std::mutex mutex;
  const std::string line = "bridge_inproc: " + call + ": " + reason + "\n";
  std::lock_guard lock(mutex);
  std::fputs(line.c_str(), stderr);
  if (const char* path = std::getenv("LFD_BRIDGE_LOG"); path && *path) {
    if (std::FILE* f = std::fopen(path, "a")) {
      std::fputs(line.c_str(), f);
      std::fclose(f);
    }
  }
}

}  // namespace lfd::bridge
