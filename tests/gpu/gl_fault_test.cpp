// A GL path that fails on a user's driver degrades instead of stopping the program (docs/gpu.md
// "Drivers and limits"), driven by the fault switch LFD_GL_FAULT: with the compute raster path
// unbuildable, `--raster auto` draws the hardware path's quilt after a one-line notice, and
// `--raster compute` exits 2 with one line naming the pass; with every allocation failing, the
// program exits 2 with one line and writes nothing.
#include <filesystem>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/apps/run_lfd.hpp"
#include "tests/test_data.hpp"
#include "util/image.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

class GlFault : public testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("gl_fault"); }
  void TearDown() override { fs::remove_all(dir_); }

  test::RunResult render(const std::string& fault, const std::string& name, const std::string& extra) const {
    const std::string scene = (test::project_data() / "scenes" / "demo.ply").string();
    return test::run_command((fault.empty() ? "" : "LFD_GL_FAULT=" + fault + " ") + std::string(LFD_EXE) +
                             " render --scene '" + scene + "' --views 6 --cols 3 --rows 2 --size 48x32 --out '" +
                             (dir_ / (name + ".png")).string() + "' --backend gl " + extra);
  }
  fs::path quilt(const std::string& name) const { return dir_ / (name + "_qs3x2a1.5.png"); }
  static int lines_containing(const std::string& text, const std::string& what) {
    std::istringstream in(text);
    int n = 0;
    for (std::string line; std::getline(in, line);) n += line.find(what) != std::string::npos;
    return n;
  }

  fs::path dir_;
};

TEST_F(GlFault, AutoDrawsTheHardwareQuiltWhenTheComputePathCannotBeBuilt) {
  for (const std::string method : {"per-view", "g2lf"}) {
    SCOPED_TRACE(method);
    const auto hardware = render("", method + "_hardware", "--method " + method + " --raster hardware");
    ASSERT_EQ(hardware.exit_code, 0) << hardware.output;
    const auto fallback = render("compute", method + "_auto", "--method " + method + " --raster auto");
    ASSERT_EQ(fallback.exit_code, 0) << fallback.output;
    EXPECT_EQ(lines_containing(fallback.output, "notice: --raster auto: the compute path failed"), 1) << fallback.output;
    EXPECT_TRUE(read_image(quilt(method + "_auto"), 4).pixels == read_image(quilt(method + "_hardware"), 4).pixels);
  }
}

TEST_F(GlFault, ComputeAskedByNameIsOneLineAndExit2) {
  const auto r = render("compute", "compute", "--raster compute");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  // One line says why (the backend's own line before it says which GL runs).
  EXPECT_EQ(lines_containing(r.output, "error"), 1) << r.output;
  EXPECT_EQ(lines_containing(r.output, "lfd render: error: compute splats: the compute raster path cannot be built"), 1)
      << r.output;
  EXPECT_FALSE(fs::exists(quilt("compute")));
}

TEST_F(GlFault, OutOfMemoryIsOneLineAndExit2WithNothingWritten) {
  const auto r = render("oom", "oom", "--raster hardware");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_EQ(lines_containing(r.output, "out of memory"), 1) << r.output;
  EXPECT_FALSE(fs::exists(quilt("oom")));
}

}  // namespace
}  // namespace lfd
