// `lfd calibrate`'s cover options (docs/calibration.md, "The cover layer"): a range that is no
// range, an index without a thickness, or two ways of giving the cover at once are refused in
// one line with exit code 2, before any photo is read, and nothing is written.
#include <filesystem>

#include <gtest/gtest.h>

#include "tests/support/run_lfd.hpp"

namespace {

namespace fs = std::filesystem;
using lfd::test::run_lfd;

struct Refusal {
  const char* options;
  const char* named;  // what the one line must name
};

TEST(CalibrateCoverCli, ImpossibleCoversAreRefusedBeforeAnyPhotoIsRead) {
  const fs::path dir = fs::temp_directory_path() / "lfd_calibrate_cover_cli";
  fs::remove_all(dir);
  const std::string out = (dir / "cal.json").string();
  for (const Refusal& r : {Refusal{"--cover-range 0.02 0.01", "--cover-range"},
                           Refusal{"--cover-range -0.01 0.01", "--cover-range"},
                           Refusal{"--cover-thickness 0.7", "--cover-thickness"},
                           Refusal{"--cover-index 1.5", "--cover-index"},
                           Refusal{"--cover-thickness 0.01 --cover-unknown", "--cover-unknown"},
                           Refusal{"--cover-sigma 0.002", "--cover-thickness"}}) {
    const auto result = run_lfd("calibrate " + dir.string() + " --out " + out + " " + r.options);
    EXPECT_EQ(result.exit_code, 2) << r.options << ": " << result.output;
    EXPECT_NE(result.output.find(r.named), std::string::npos) << r.options << ": " << result.output;
  }
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
