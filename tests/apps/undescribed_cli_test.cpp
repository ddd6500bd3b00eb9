// `lfd patterns --screen WxH --dpi D` and `lfd calibrate DIR` on a panel nobody described
// (docs/calibration.md, "A panel nobody described"): the coarse set is written without any
// lens description, and photos too few to tell the slant's sign, or none of the probes, are
// refused in one line with exit code 2 and nothing written.
#include <filesystem>

#include <gtest/gtest.h>

#include "tests/support/run_lfd.hpp"

namespace {

namespace fs = std::filesystem;
using lfd::test::run_lfd;

fs::path fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("lfd_undescribed_cli_" + name);
  fs::remove_all(dir);
  return dir;
}

// The coarse set of a small panel, and its patterns copied in as the "photos" of pos1: every
// pattern but the probe steps `drop` leaves out.
fs::path coarse_folder(const std::string& name, bool drop_later_steps, bool drop_probes) {
  const fs::path dir = fresh(name);
  const auto r = run_lfd("patterns --screen 320x200 --dpi 60 --min-lpi 8 --max-lpi 20 --out " +
                         dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("lens probes"), std::string::npos) << r.output;
  const fs::path pos = dir / "captures" / "pos1";
  fs::create_directories(pos);
  for (const auto& f : fs::directory_iterator(dir / "patterns")) {
    const std::string file = f.path().filename().string();
    if (f.path().extension() != ".png") continue;
    const bool probe = file.find("_probe_") != std::string::npos;
    if (probe && drop_probes) continue;
    if (probe && drop_later_steps && file.find("_0of") == std::string::npos) continue;
    fs::copy_file(f.path(), pos / file);
  }
  return dir;
}

TEST(UndescribedCli, OnePhotoPerProbeCannotTellTheSlantsSign) {
  const fs::path dir = coarse_folder("one_step", true, false);
  const auto r = run_lfd("calibrate " + dir.string() + " --out " + (dir / "cal.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("slant's sign"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("_1of3"), std::string::npos) << r.output;  // names a missing photo
  EXPECT_FALSE(fs::exists(dir / "fine"));
  EXPECT_FALSE(fs::exists(dir / "cal.json"));
}

TEST(UndescribedCli, NoProbePhotosAreNamed) {
  const fs::path dir = coarse_folder("no_probes", false, true);
  const auto r = run_lfd("calibrate " + dir.string() + " --out " + (dir / "cal.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("no photos of the lens probes"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "fine"));
}

// `lfd calibrate --live DIR` on the probes' folder: the probes are round 1, so one round is
// too few, and a --display beside them is a second description; both refused before anything
// is shown or saved.
TEST(UndescribedCli, LiveNeedsTwoRoundsAndNoSecondDescription) {
  const fs::path dir = fresh("live");
  ASSERT_EQ(run_lfd("patterns --screen 320x200 --dpi 60 --min-lpi 8 --max-lpi 20 --out " +
                    dir.string()).exit_code, 0);
  const std::string live = "calibrate --live " + dir.string() + " --simulate " +
                           (dir / "truth.json").string() + " --out " + (dir / "cal.json").string();
  auto r = run_lfd(live + " --rounds 1");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--rounds 1: a panel nobody described needs 2 rounds"), std::string::npos)
      << r.output;
  r = run_lfd(live + " --display " + (dir / "truth.json").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("not both"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "live"));
  EXPECT_FALSE(fs::exists(dir / "cal.json"));
}

TEST(UndescribedCli, ScreenNeedsDpiAndASize) {
  const fs::path dir = fresh("bad_screen");
  auto r = run_lfd("patterns --screen 1920x1200 --out " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--dpi"), std::string::npos) << r.output;
  r = run_lfd("patterns --screen 1920by1200 --dpi 200 --out " + dir.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--screen 1920by1200"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "patterns" / "manifest.json"));
}

}  // namespace
