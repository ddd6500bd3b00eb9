#pragma once
// Where tests find data: the project's data/ and the shared real data beside the repo
// (../shared/data). Tests that need the shared data skip with a message when it is absent.
#include <unistd.h>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lfd::test {

inline std::filesystem::path shared_data() { return LFD_SHARED_DATA_DIR; }
inline std::filesystem::path project_data() { return LFD_DATA_DIR; }

inline bool has_shared_data() { return std::filesystem::exists(shared_data() / "calibrations"); }

#define LFD_REQUIRE_SHARED_DATA()                                                         \
  do {                                                                                    \
    if (!::lfd::test::has_shared_data())                                                  \
      GTEST_SKIP() << "shared data not found at " << ::lfd::test::shared_data().string()  \
                   << " (tests that use the real calibrations and scenes need it)";       \
  } while (0)

inline std::vector<std::filesystem::path> shared_calibrations() {
  std::vector<std::filesystem::path> files;
  if (!has_shared_data()) return files;
  for (const auto& e : std::filesystem::directory_iterator(shared_data() / "calibrations"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// A fresh temporary directory per test.
inline std::filesystem::path temp_dir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("lfd_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace lfd::test
