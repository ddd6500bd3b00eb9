// `lfd rgbd-quilt` through the real program: the quilt file is the library's quilt of the same
// PNG, named with its tiling; --backend gl writes the same; bad options, settings and names are
// one line, exit 2 and no file.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "rgbd/rgbd_quilt.hpp"
#include "rgbd/rgbd_view_model.hpp"
#include "tests/support/run_lfd.hpp"
#include "tests/rgbd/rgbd_fixture.hpp"
#include "tests/test_data.hpp"
#include "util/image.hpp"

namespace lfd::rgbd {
namespace {

namespace fs = std::filesystem;

// A quoted shell word (appended piecewise: GCC 12 warns falsely on "'" + string).
std::string q(const fs::path& p) {
  std::string word = "'";
  word += p.string();
  word += "'";
  return word;
}

class RgbdQuiltCli : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = lfd::test::temp_dir("rgbd_quilt_cli");
    // The layered fixture, colour 96 x 64 with the depth on the left, as an 8-bit PNG.
    write_png(input(), to_uint8(test::layered_rgbd_frame(96, 64, DepthLocation::left)));
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path input() const { return dir_ / "layers_rgbd.png"; }
  size_t files() const {
    return size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
  }
  // What the library makes of the PNG with these options and 9 views.
  Image8 library_quilt(const RgbdOptions& o) const {
    const ImageF frame = to_float(read_image(input(), 3));
    return to_uint8(render_rgbd_quilt(frame, o, rgbd_quilt_layout(frame.width, frame.height,
                                                                  o.depth_loc, 9)));
  }
  fs::path dir_;
};

TEST_F(RgbdQuiltCli, WritesTheLibrarysQuiltUnderItsTilingName) {
  const auto r = lfd::test::run_lfd("rgbd-quilt " + q(input()) + " " + q(dir_ / "out.png") +
                                    " --depth-loc left --depthiness 3 --focus 0.01 --views 9");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path written = dir_ / "out_qs3x3a1.5.png";
  ASSERT_TRUE(fs::exists(written)) << r.output;
  RgbdOptions o;
  o.depth_loc = DepthLocation::left;
  o.depthiness = 3;
  o.focus = 0.01;
  const Image8 quilt = read_image(written, 3);
  EXPECT_EQ(quilt.pixels, library_quilt(o).pixels);
  // lfd interlace takes it as it takes any quilt: the tiling from the name.
  const auto panel = lfd::test::run_lfd(
      "interlace --calibration " + q(lfd::test::fixture_calibration("LKG-2K-04409.visual.json")) +
      " --quilt " + q(written) + " --out " + q(dir_ / "panel.png"));
  ASSERT_EQ(panel.exit_code, 0) << panel.output;
  EXPECT_NE(panel.output.find("9 views in 3x3 tiles"), std::string::npos) << panel.output;
}

TEST_F(RgbdQuiltCli, TheGlBackendWritesTheSameQuiltAndSettingsFilesWork) {
  std::ofstream(dir_ / "rgbd.json")
      << R"({"depth_loc": 3, "depthiness": 2.5, "depth_inversion": 0, "chroma_depth": 0, "zoom": 1.2})";
  const auto r = lfd::test::run_lfd("rgbd-quilt " + q(input()) + " " + q(dir_ / "gl.png") +
                                    " --settings " + q(dir_ / "rgbd.json") + " --views 9 --backend gl");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  RgbdOptions o;
  o.depth_loc = DepthLocation::left;
  o.depthiness = 2.5;
  o.zoom = 1.2;
  const Image8 quilt = read_image(dir_ / "gl_qs3x3a1.5.png", 3);
  const Image8 cpu = library_quilt(o);
  ASSERT_EQ(quilt.pixels.size(), cpu.pixels.size());
  size_t off = 0;
  for (size_t i = 0; i < cpu.pixels.size(); ++i) off += std::abs(int(quilt.pixels[i]) - int(cpu.pixels[i])) > 1;
  EXPECT_LE(off, cpu.pixels.size() / 1000);
}

TEST_F(RgbdQuiltCli, BadInputIsOneLineExitTwoAndNoFile) {
  std::ofstream(dir_ / "bad.json") << R"({"depthiness": "deep"})";
  const size_t before = files();
  const struct {
    std::string args, names;
  } cases[] = {
      {" --depth-loc left --zoom 9", "zoom"},
      {" --depth-loc middle", "depth_loc"},
      {" --settings " + q(dir_ / "bad.json"), "bad.json: RGB-D settings: depthiness"},
      {" --settings " + q(dir_ / "missing.json"), "missing.json"},
  };
  for (const auto& c : cases) {
    const auto r = lfd::test::run_lfd("rgbd-quilt " + q(input()) + " " + q(dir_ / "o.png") + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.output;
    EXPECT_NE(r.output.find(c.names), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << r.output;  // one line
  }
  // A name whose tiling is not the quilt's.
  const auto r = lfd::test::run_lfd("rgbd-quilt " + q(input()) + " " + q(dir_ / "o_qs5x9a1.5.png") +
                                    " --views 9");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("names a 5x9 quilt"), std::string::npos) << r.output;
  EXPECT_EQ(files(), before);
}

}  // namespace
}  // namespace lfd::rgbd
