// The device's limits are read, not assumed (gpu/gl/gl_limits.hpp; docs/gpu.md "Drivers and
// limits"): LFD_GL_LIMITS lowers them and is checked like any input; with a GPU's smaller limits
// (NVIDIA's 48 KiB of shared memory and 1024 invocations, a 16384-texel texture and a storage
// block of 4 MiB, far below any GPU's, so the tile rasterizers split every frame into passes)
// the compute paths write the same bytes as with llvmpipe's own.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gpu/gl/gl_limits.hpp"
#include "tests/apps/run_lfd.hpp"
#include "tests/test_data.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

namespace lfd::gpu {
namespace {

namespace fs = std::filesystem;

TEST(GlLimits, LfdGlLimitsLowersOnlyTheNamedLimits) {
  GlLimits device;
  device.storage_block_bytes = 128ll << 20;
  device.shared_bytes = 32768;
  device.invocations = 1024;
  device.work_groups_x = 65535;
  device.texture_size = 16384;
  device.array_layers = 2048;
  const GlLimits lowered = lower_gl_limits(device, "storage=1048576,shared=49152,texture=4096");
  EXPECT_EQ(lowered.storage_block_bytes, 1048576);
  EXPECT_EQ(lowered.shared_bytes, 32768);  // above the device's own: unchanged
  EXPECT_EQ(lowered.texture_size, 4096);
  EXPECT_EQ(lowered.invocations, 1024);
  EXPECT_EQ(lowered.array_layers, 2048);
}

TEST(GlLimits, AMalformedLfdGlLimitsNamesTheField) {
  const GlLimits device{.storage_block_bytes = 1 << 20, .texture_size = 4096};
  for (const char* bad : {"storage", "storage=", "storage=-1", "storage=12abc", "colour=4"}) {
    SCOPED_TRACE(bad);
    try {
      lower_gl_limits(device, bad);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("LFD_GL_LIMITS"), std::string::npos) << e.what();
    }
  }
}

// The written image of `lfd render ARGS --out DIR/NAME.png` (with the quilt suffix), run with
// `environment` before the program.
Image8 rendered(const fs::path& dir, const std::string& environment, const std::string& args, const std::string& name) {
  const auto r = test::run_command(environment + " " + std::string(LFD_EXE) + " render " + args + " --out '" +
                                   (dir / (name + ".png")).string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().starts_with(name + "_qs")) return read_image(entry.path(), 4);
  ADD_FAILURE() << "no quilt for " << name << ": " << r.output;
  return {};
}

TEST(GlLimits, ComputePathsWriteTheSameBytesUnderAGpusSmallerLimits) {
  const fs::path dir = test::temp_dir("gl_limits");
  const std::string small = "LFD_GL_LIMITS=storage=4194304,shared=49152,invocations=1024,texture=16384";
  const std::string voxels = (dir / "scene.voxels").string();
  ASSERT_EQ(test::run_lfd("scene generate --kind voxels --level 5 --out '" + voxels + "'").exit_code, 0);
  const std::string demo = (test::project_data() / "scenes" / "demo.ply").string();
  const std::string grid = " --views 12 --cols 4 --rows 3 --size 64x48 --chunks 16 --backend gl --raster compute";
  for (const auto& [name, args] : {std::pair{"splats", "--scene '" + demo + "' --method per-view" + grid},
                                   std::pair{"splats_g2lf", "--scene '" + demo + "' --method g2lf" + grid},
                                   std::pair{"voxels", "--scene '" + voxels + "' --method per-view" + grid}}) {
    SCOPED_TRACE(name);
    const Image8 own = rendered(dir, "", args, std::string(name) + "_own");
    const Image8 lowered = rendered(dir, small, args, std::string(name) + "_small");
    ASSERT_FALSE(own.pixels.empty());
    EXPECT_TRUE(own.pixels == lowered.pixels) << "the images differ under smaller limits";
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lfd::gpu
