// `lfd --version` and `lfd version`: the version line, and that an installed program finds its
// bundled data relative to itself (<prefix>/bin/lfd -> <prefix>/share/lfd).
#include <array>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>
#include <system_error>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "tests/support/run_lfd.hpp"
#include "tests/test_data.hpp"

namespace {

namespace fs = std::filesystem;

// "lfd 0.1.0 (commit abc1234, built 2026-11-22)"; the commit may be "-dirty" or "unknown".
const std::regex kVersionLine(
    R"(lfd \d+\.\d+\.\d+ \(commit ([0-9a-f]{7,}(-dirty)?|unknown), built \d{4}-\d{2}-\d{2}\))");

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

// The folder after "data: " in the output of `lfd version`.
std::string data_folder(const std::string& output) {
  const auto at = output.find("data: ");
  if (at == std::string::npos) return {};
  const auto begin = at + 6;
  return output.substr(begin, output.find('\n', begin) - begin);
}

TEST(VersionCli, VersionFlagPrintsOneVersionLineAndExitsZero) {
  const auto r = lfd::test::run_lfd("--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_TRUE(std::regex_match(first_line(r.output), kVersionLine)) << r.output;
  EXPECT_EQ(r.output, first_line(r.output) + "\n");
}

TEST(VersionCli, VersionCommandPrintsTheSameLineAndTheDataFolder) {
  const auto flag = lfd::test::run_lfd("--version");
  const auto r = lfd::test::run_lfd("version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(first_line(r.output), first_line(flag.output));
  EXPECT_NE(r.output.find("\ndata: "), std::string::npos) << r.output;
}

TEST(VersionCli, VersionCommandRefusesArguments) {
  EXPECT_EQ(lfd::test::run_lfd("version --frobnicate").exit_code, 2);
}

TEST(VersionCli, BuildTreeProgramFindsTheSourceData) {
  const auto r = lfd::test::run_lfd("version");
  std::error_code ec;
  EXPECT_TRUE(fs::equivalent(data_folder(r.output), lfd::test::project_data(), ec)) << r.output;
}

TEST(VersionCli, InstalledProgramFindsShareLfdBesideItsBinFolder) {
  // A prefix laid out as `cmake --install` does, with the program hard-linked (or copied) in:
  // the program reads its own path, not a compiled-in one.
  const fs::path prefix = fs::path(LFD_BINARY_DIR) / "version_test_prefix";
  fs::remove_all(prefix);
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share/lfd/displays");
  std::error_code ec;
  fs::create_hard_link(LFD_EXE, prefix / "bin/lfd", ec);
  if (ec) fs::copy_file(LFD_EXE, prefix / "bin/lfd");
  const std::string exe = (prefix / "bin/lfd").string();

  const auto installed = lfd::test::run_command(exe + " version");
  EXPECT_EQ(installed.exit_code, 0);
  EXPECT_EQ(data_folder(installed.output), (prefix / "share/lfd").string()) << installed.output;

  // $LFD_DATA_DIR overrides it.
  const auto overridden = lfd::test::run_command("LFD_DATA_DIR=/opt/lfd-data " + exe + " version");
  EXPECT_EQ(data_folder(overridden.output), "/opt/lfd-data") << overridden.output;
  fs::remove_all(prefix);
}

}  // namespace
