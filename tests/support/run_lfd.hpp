#pragma once
// The CLI runner every command-line test shares: runs the real `lfd` program (LFD_EXE, set by the
// test target) with arguments and captures its exit code and output, through a pipe rather than a
// shared log file, since CTest runs the tests in parallel.
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
