// The compute passes do not depend on how the driver schedules them (docs/gpu.md "Drivers and
// limits"): llvmpipe runs a dispatch's work groups on LP_NUM_THREADS threads, so a missing
// barrier or an assumption about the order groups run in shows as a difference between one
// thread and many. Each compute path of `lfd render --backend gl` (Gaussians per view and G2LF
// planes, voxels per view and V2LF planes, the direct panel pass) writes the same bytes with
// LP_NUM_THREADS=1 and LP_NUM_THREADS=8.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/apps/run_lfd.hpp"
#include "tests/test_data.hpp"
#include "util/image.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;

class SchedulingIndependence : public testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("scheduling"); }
  void TearDown() override { fs::remove_all(dir_); }

  // Renders with `threads` llvmpipe threads (`{out}` in args: the output's path); returns the
  // written image's pixels.
  Image8 render(std::string args, int threads, const std::string& name) const {
    const fs::path out = dir_ / (name + "_t" + std::to_string(threads) + ".png");
    args.replace(args.find("{out}"), 5, out.string());
    const auto r = test::run_command("LP_NUM_THREADS=" + std::to_string(threads) + " " + std::string(LFD_EXE) +
                                     " render " + args);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    for (const auto& entry : fs::directory_iterator(dir_)) {  // the quilt's name gets its _qs suffix
      const std::string file = entry.path().filename().string();
      if (file.starts_with(name + "_t" + std::to_string(threads)) && entry.path().extension() == ".png")
        return read_image(entry.path(), 4);
    }
    ADD_FAILURE() << "no image written for " << name << ": " << r.output;
    return {};
  }
  void expect_same_with_one_thread_and_many(const std::string& args, const std::string& name) const {
    SCOPED_TRACE(name);
    const Image8 one = render(args, 1, name);
    const Image8 many = render(args, 8, name);
    ASSERT_EQ(one.width, many.width);
    ASSERT_EQ(one.height, many.height);
    ASSERT_FALSE(one.pixels.empty());
    size_t differing = 0;
    for (size_t i = 0; i < one.pixels.size(); ++i) differing += one.pixels[i] != many.pixels[i];
    EXPECT_EQ(differing, 0u) << "bytes differing between LP_NUM_THREADS=1 and 8";
  }

  fs::path dir_;
};

TEST_F(SchedulingIndependence, GaussianComputePathsWriteTheSameBytesOnOneThreadAndMany) {
  const std::string scene = "--scene '" + (test::project_data() / "scenes" / "demo.ply").string() + "'";
  const std::string common = scene + " --views 12 --cols 4 --rows 3 --size 64x48 --chunks 32 --precision f32" +
                             " --backend gl --raster compute --out '{out}'";
  expect_same_with_one_thread_and_many(common + " --method per-view", "splats_per_view");
  expect_same_with_one_thread_and_many(common + " --method g2lf", "splats_g2lf");
}

TEST_F(SchedulingIndependence, VoxelComputePathsWriteTheSameBytesOnOneThreadAndMany) {
  const std::string scene = (dir_ / "scene.voxels").string();
  ASSERT_EQ(test::run_lfd("scene generate --kind voxels --level 5 --out '" + scene + "'").exit_code, 0);
  const std::string common = "--scene '" + scene + "' --views 6 --cols 3 --rows 2 --size 48x32 --chunks 16" +
                             " --backend gl --raster compute --out '{out}'";
  expect_same_with_one_thread_and_many(common + " --method per-view", "voxels_per_view");
  expect_same_with_one_thread_and_many(common + " --method v2lf", "voxels_v2lf");
}

TEST_F(SchedulingIndependence, DirectPanelPassWritesTheSameBytesOnOneThreadAndMany) {
  const std::string calibration = test::fixture_calibration("LKG-APW92011.visual.json").string();
  const std::string scene = (test::project_data() / "scenes" / "demo.ply").string();
  expect_same_with_one_thread_and_many("--scene '" + scene + "' --calibration '" + calibration +
                                           "' --method g2lf --chunks 16 --backend gl --direct --panel '{out}'",
                                       "direct");
}

}  // namespace
}  // namespace lfd
