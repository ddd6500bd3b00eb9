#pragma once
// The fixture of the bad-scene-file tests (scene_bad_input_test.cpp, scene_formats_bad_input_test
// .cpp): a scratch folder per test, files written into it, and the check every bad file must pass:
// an InputError of one line naming the file and the problem.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/gaussian_io.hpp"
#include "util/error.hpp"

namespace lfd::scene {

class SceneBadInputFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("lfd_scene_bad_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_suite()->name() + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name, const std::string& bytes) {
    const std::filesystem::path p = dir_ / name;
    std::ofstream(p, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    return p;
  }

  // Loading must throw InputError whose message names the file and contains `problem`.
  void expect_rejected(const std::filesystem::path& path, const std::string& problem) {
    try {
      scene::load_gaussian_scene(path);
      FAIL() << path << " loaded without error";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path.string()), std::string::npos) << message;
      EXPECT_NE(message.find(problem), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    }
  }

  std::filesystem::path dir_;
};

}  // namespace lfd::scene
