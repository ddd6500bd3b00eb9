#pragma once
// Runs the real `lfd` program (LFD_EXE) with arguments; captures its exit code and output.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace lfd::test {

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout + stderr
};

// Runs a shell command line (stdout + stderr captured).
inline RunResult run_command(const std::string& command) {
  RunResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  while (fgets(buf.data(), int(buf.size()), pipe)) r.output += buf.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

inline RunResult run_lfd(const std::string& args) {
  return run_command(std::string(LFD_EXE) + " " + args);
}

}  // namespace lfd::test
