// `lfd scene`: generate writes a loadable PLY; info reports counts, degree and bounds (also as
// JSON); bad input exits 2 with a one-line message naming the file.
#include <unistd.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/run_lfd.hpp"
#include "tests/test_data.hpp"

#include <nlohmann/json.hpp>

namespace {

using Result = lfd::test::RunResult;
using lfd::test::run_lfd;

std::filesystem::path temp_dir() { return lfd::test::scratch_dir("scene_cli"); }

TEST(SceneCli, GenerateThenInfoAsJson) {
  const auto out = temp_dir() / "corridor.ply";
  const Result gen = run_lfd("scene generate --kind corridor --count 5000 --seed 4 --sh-degree 2 --out " +
                         out.string());
  ASSERT_EQ(gen.exit_code, 0) << gen.output;
  const Result info = run_lfd("scene info --json " + out.string());
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const auto j = nlohmann::json::parse(info.output);
  EXPECT_EQ(j["gaussians"], 5000);
  EXPECT_EQ(j["sh_degree"], 2);
  EXPECT_GT(j["bounds_all"]["max"][2].get<double>(), 11.0);  // the corridor's end wall
}

TEST(SceneCli, InfoReadsTheBundledDemoScene) {
  const Result info = run_lfd(std::string("scene info --json ") + LFD_SOURCE_DIR "/data/scenes/demo.ply");
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const auto j = nlohmann::json::parse(info.output);
  EXPECT_EQ(j["gaussians"], 27000);
  EXPECT_EQ(j["sh_degree"], 1);
  EXPECT_LT(j["radius"].get<double>(), 8.0);
}

TEST(SceneCli, BadSceneFileIsExitTwoNamingTheFile) {
  const auto bad = temp_dir() / "truncated.ply";
  std::ofstream(bad) << "ply\nformat binary_little_endian 1.0\nelement vertex 10\n"
                        "property float x\nend_header\n";
  const Result r = run_lfd("scene info " + bad.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(bad.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("truncated"), std::string::npos) << r.output;
}

TEST(SceneCli, UnknownKindAndMissingOutputAreExitTwo) {
  EXPECT_EQ(run_lfd("scene generate --kind nebula --out x.ply").exit_code, 2);
  EXPECT_EQ(run_lfd("scene generate --kind tabletop").exit_code, 2);
  EXPECT_EQ(run_lfd("scene").exit_code, 2);
  EXPECT_EQ(run_lfd("scene --help").exit_code, 0);
}

TEST(SceneCli, ConvertWritesSpzAndRefusesBadInputWritingNothing) {
  const auto spz = temp_dir() / "playbot.spz";
  std::filesystem::remove(spz);
  const Result ok = run_lfd(std::string("scene convert ") + LFD_SOURCE_DIR "/data/scenes/playbot.sog " + spz.string());
  ASSERT_EQ(ok.exit_code, 0) << ok.output;
  const auto j = nlohmann::json::parse(run_lfd("scene info --json " + spz.string()).output);
  EXPECT_EQ(j["gaussians"], 31000);
  EXPECT_EQ(j["sh_degree"], 2);
  // A truncated SOG: one line naming it, exit 2, no output file.
  const auto bad = temp_dir() / "truncated.sog";
  std::ifstream in(LFD_SOURCE_DIR "/data/scenes/playbot.sog", std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  std::ofstream(bad, std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  const auto out = temp_dir() / "never.ply";
  std::filesystem::remove(out);
  const Result r = run_lfd("scene convert " + bad.string() + " " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find(bad.string()), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
