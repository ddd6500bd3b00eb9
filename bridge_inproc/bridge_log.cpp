#include "bridge_inproc/bridge_log.hpp"

#include <cstdio>
#include <cstdlib>
#include <mutex>

namespace lfd::bridge {

void refuse(const std::string& reason) { throw BadCall(reason); }

namespace {

std::mutex log_mutex;

void write_line(const std::string& call, const std::string& text, bool to_stderr) {
  const std::string line = "bridge_inproc: " + call + ": " + text + "\n";
  std::lock_guard lock(log_mutex);
  if (to_stderr) std::fputs(line.c_str(), stderr);
  if (const char* path = std::getenv("LFD_BRIDGE_LOG"); path && *path) {
    if (std::FILE* f = std::fopen(path, "a")) {
      std::fputs(line.c_str(), f);
      std::fclose(f);
    }
  }
}

}  // namespace

void log_line(const std::string& call, const std::string& reason) { write_line(call, reason, true); }

void log_detail(const std::string& call, const std::string& text) { write_line(call, text, false); }

}  // namespace lfd::bridge
