#pragma once
// Where tests find data:
//   fixtures()      tests/data: small real files in the repository (calibrations of real units,
//                   the three-points scenes in every format), so a fresh clone runs every test;
//   project_data()  data/: what the program bundles (the demo scene, display templates);
//   shared_data()   ../shared/data beside the repository: large optional files only (the
//                   guitar scene). A test that needs one starts with LFD_REQUIRE_SHARED_FILE,
//                   which skips it with a message when the file is absent.
#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lfd::test {

inline std::filesystem::path fixtures() { return LFD_TEST_DATA_DIR; }
inline std::filesystem::path project_data() { return LFD_DATA_DIR; }
inline std::filesystem::path shared_data() { return LFD_TEST_SHARED_DATA_DIR; }

// tests/data/calibrations/<name>: visual.json files of real units.
inline std::filesystem::path fixture_calibration(const std::string& name) {
  return fixtures() / "calibrations" / name;
}
// tests/data/scenes/<name>.
inline std::filesystem::path fixture_scene(const std::string& name) {
  return fixtures() / "scenes" / name;
}

// Every calibration fixture, sorted by name.
inline std::vector<std::filesystem::path> fixture_calibrations() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(fixtures() / "calibrations"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The one skip helper: `relative` under ../shared/data, e.g. "scenes/guitar.compressed.ply".
#define LFD_REQUIRE_SHARED_FILE(relative)                                                 \
  do {                                                                                    \
    if (!std::filesystem::exists(::lfd::test::shared_data() / (relative)))                \
      GTEST_SKIP() << "optional shared file not found: "                                  \
                   << (::lfd::test::shared_data() / (relative)).string();                 \
  } while (0)

inline std::filesystem::path temp_dir_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("lfd_test_" + name + "_" + std::to_string(::getpid()));
}

// A fresh temporary directory per test.
inline std::filesystem::path temp_dir(const std::string& name) {
  const std::filesystem::path dir = temp_dir_path(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// One temporary directory for the tests of a file, made on first use and kept, not emptied, for
// the files several calls write and read in turn.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const std::filesystem::path dir = temp_dir_path(name);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace lfd::test
