// `lfd play` full screen under Xvfb (CMakeLists.txt): the panel on screen equals `lfd interlace`
// of the same quilt (an image: >= 40 dB; a video: the decoded frame on screen, >= 35 dB); bad
// files are one line naming the file and exit 2, and a playlist skips them with a notice.
#include <filesystem>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>

#include "media/synthetic_quilt.hpp"
#include "media/video_decoder.hpp"
#include "render/image_metrics.hpp"
#include "tests/rgbd/rgbd_fixture.hpp"
#include "tests/support/run_lfd.hpp"
#include "util/image.hpp"

namespace lfd {
namespace {

namespace fs = std::filesystem;
using test::run_lfd;

const fs::path kDir = fs::temp_directory_path() / "lfd_play_window_test";
const std::string kCalibration =
    (fs::path(LFD_TEST_DATA_DIR) / "calibrations" / "LKG-PORT-portrait.visual.json").string();

render::QuiltLayout layout(int cols, int rows, int tile_w, int tile_h, double aspect) {
  render::QuiltLayout q;
  q.cols = cols;
  q.rows = rows;
  q.views = cols * rows;
  q.aspect = aspect;
  q.width = cols * tile_w;
  q.height = rows * tile_h;
  return q;
}

fs::path write_quilt_png(const std::string& stem, const render::QuiltLayout& q) {
  fs::create_directories(kDir);
  const fs::path path = kDir / (stem + render::quilt_suffix(q.cols, q.rows, q.aspect) + ".png");
  write_png(path, media::synthetic_quilt(q));
  return path;
}

fs::path write_quilt_video(const std::string& stem, const render::QuiltLayout& q, int frames) {
  fs::create_directories(kDir);
  const fs::path path = kDir / (stem + render::quilt_suffix(q.cols, q.rows, q.aspect) + ".mp4");
  if (!fs::exists(path)) media::write_synthetic_quilt_video(path, q, frames, media::EncoderOptions{});
  return path;
}

// `lfd interlace` of a quilt file: the reference panel.
ImageF interlace_reference(const fs::path& quilt) {
  const fs::path out = kDir / (quilt.stem().string() + ".reference.png");
  const auto r = run_lfd("interlace --calibration " + kCalibration + " --quilt " + quilt.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return to_float(read_image(out));
}

// `lfd play FILE... --frames N --screenshot`: what the window showed. `env`: variables before
// the program ("MESA_GL_VERSION_OVERRIDE=3.1 ").
ImageF play_screenshot(const std::string& files, const std::string& extra, const std::string& tag,
                       std::string* output = nullptr, const std::string& env = "") {
  const fs::path shot = kDir / (tag + ".screenshot.png");
  fs::remove(shot);
  const auto r = test::run_command(env + LFD_EXE + " play " + files + " --calibration " + kCalibration +
                                   " --frames 4 --screenshot " + shot.string() + " " + extra);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("its monitor"), std::string::npos) << "not full screen on the display: " << r.output;
  if (output) *output = r.output;
  return fs::exists(shot) ? to_float(read_image(shot)) : ImageF();
}

TEST(PlayWindow, QuiltImageEqualsInterlace) {
  const fs::path quilt = write_quilt_png("image", layout(8, 6, 96, 128, 0.75));
  const ImageF reference = interlace_reference(quilt);
  const ImageF shown = play_screenshot(quilt.string(), "", "image");
  ASSERT_EQ(shown.width, 1536);
  ASSERT_EQ(shown.height, 2048);
  EXPECT_GE(render::psnr(shown, reference), 40.0);
}

// A quilt whose grid and aspect differ from the display's: the interlacer's view mapping and
// letterboxing, exactly as `lfd interlace` does them (never stretched).
TEST(PlayWindow, OtherGridAndAspectEqualsInterlace) {
  const fs::path quilt = write_quilt_png("square", layout(5, 9, 100, 100, 1.0));
  const ImageF reference = interlace_reference(quilt);
  const ImageF shown = play_screenshot(quilt.string(), "", "square");
  ASSERT_FALSE(shown.empty());
  EXPECT_GE(render::psnr(shown, reference), 40.0);
  // Letterboxed: the rows at the top and bottom of the panel are black in both.
  double top = 0;
  for (int x = 0; x < shown.width; ++x) top += shown.at(x, 0, 1);
  EXPECT_LT(top / shown.width, 0.01);
}

// The video frame on screen (paused at 0.2 s) against `lfd interlace` of that frame decoded here.
void expect_video_frame_equals_interlace(const std::string& extra, const std::string& tag,
                                         const std::string& env = "", std::string* played = nullptr) {
  const fs::path video = write_quilt_video("video", layout(8, 6, 48, 64, 0.75), 12);
  std::string output;
  const ImageF shown = play_screenshot(video.string(), "--pause-at 0.2 " + extra, tag, &output, env);
  if (played) *played = output;
  ASSERT_FALSE(shown.empty());
  // The frame on screen, as the player reports it, and the same frame decoded here.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(output, m, std::regex("frame (\\d+) \\(")) ) << output;
  const int on_screen = std::stoi(m[1]);
  EXPECT_EQ(on_screen, 6);  // the frame shown at 0.2 s of a 30 fps video
  media::VideoDecoder decoder(video, {false, 1});
  decoder.seek(0.2);
  const auto frame = decoder.next_frame();
  ASSERT_TRUE(frame);
  ASSERT_EQ(frame->index, on_screen);
  const fs::path decoded = kDir / ("decoded" + render::quilt_suffix(8, 6, 0.75) + ".png");
  write_png(decoded, media::yuv_to_rgb(*frame));
  EXPECT_GE(render::psnr(shown, interlace_reference(decoded)), 35.0);
}

TEST(PlayWindow, VideoFrameOnScreenEqualsInterlaceOfDecodedFrame) { expect_video_frame_equals_interlace("", "video"); }

// An RGB-D image (colour and depth side by side, the rgbd tests' layered fixture): the panel
// on screen equals `lfd interlace` of `lfd rgbd-quilt`'s CPU quilt of it (the GL views match the
// CPU's on 99.9 % of pixels, tests/rgbd/gl_rgbd_views_test.cpp).
TEST(PlayWindow, RgbdImageEqualsInterlaceOfRgbdQuilt) {
  fs::create_directories(kDir);
  const fs::path frame = kDir / "layers_rgbd.png";
  write_png(frame, to_uint8(rgbd::test::layered_rgbd_frame(160, 120, rgbd::DepthLocation::right)));
  const auto made = run_lfd("rgbd-quilt " + frame.string() + " " + (kDir / "rgbd_reference.png").string() +
                            " --calibration " + kCalibration + " --depthiness 2 --backend cpu");
  ASSERT_EQ(made.exit_code, 0) << made.output;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(made.output, m, std::regex("wrote (\\S+_qs\\S+\\.png)"))) << made.output;
  const ImageF shown = play_screenshot(frame.string(), "--rgbd --depthiness 2", "rgbd");
  ASSERT_FALSE(shown.empty());
  EXPECT_GE(render::psnr(shown, interlace_reference(m[1].str())), 35.0);
  // Not the flat picture: the same frame shown without depth differs.
  EXPECT_LT(render::psnr(shown, play_screenshot(frame.string(), "--rgbd --depthiness 0.1", "rgbd-flat")), 35.0);
}

// OpenGL ES 3.1 (docs/arm.md): asked for (--gl es, LFD_GL=es), or taken by itself when desktop GL
// is capped below 4.5 as on a Raspberry Pi 5 (Mesa's MESA_GL_VERSION_OVERRIDE=3.1 caps desktop
// contexts only): the same panel on screen as `lfd interlace` gives, the image and the video.
struct GlFlavour {
  const char* name;
  const char* env;   // before the program
  const char* flag;  // on its command line
};

class PlayWindowOnOpenGlEs : public testing::TestWithParam<GlFlavour> {
 protected:
  std::string extra() const { return std::string(GetParam().flag) + " --info"; }
  std::string tag(const std::string& what) const { return what + "-" + GetParam().name; }
  // The player said it ran on ES, and a fallback said why once.
  void expect_es(const std::string& output) const {
    EXPECT_NE(output.find("[OpenGL ES path]"), std::string::npos) << output;
    const bool capped = std::string(GetParam().env).find("MESA_GL_VERSION_OVERRIDE") != std::string::npos;
    const size_t first = output.find("notice: no desktop OpenGL 4.5 (");
    EXPECT_EQ(first != std::string::npos, capped) << output;
    if (first != std::string::npos) {
      EXPECT_EQ(output.find("notice: no desktop OpenGL 4.5 (", first + 1), std::string::npos) << output;
    }
  }
};

TEST_P(PlayWindowOnOpenGlEs, QuiltImageEqualsInterlace) {
  const fs::path quilt = write_quilt_png("image", layout(8, 6, 96, 128, 0.75));
  const ImageF reference = interlace_reference(quilt);
  std::string output;
  const ImageF shown = play_screenshot(quilt.string(), extra(), tag("image"), &output, GetParam().env);
  expect_es(output);
  ASSERT_EQ(shown.width, 1536);
  ASSERT_EQ(shown.height, 2048);
  EXPECT_GE(render::psnr(shown, reference), 40.0);
}

TEST_P(PlayWindowOnOpenGlEs, VideoFrameOnScreenEqualsInterlaceOfDecodedFrame) {
  std::string output;
  expect_video_frame_equals_interlace(extra(), tag("video"), GetParam().env, &output);
  expect_es(output);
  EXPECT_NE(output.find("decoder: software"), std::string::npos) << output;
}

// An RGB-D picture: the views the ES context makes (RGBA32F passes: EXT_color_buffer_float) show
// what desktop GL shows.
TEST_P(PlayWindowOnOpenGlEs, RgbdImageEqualsTheDesktopOne) {
  fs::create_directories(kDir);
  const fs::path frame = kDir / "layers_es_rgbd.png";
  write_png(frame, to_uint8(rgbd::test::layered_rgbd_frame(160, 120, rgbd::DepthLocation::right)));
  const ImageF desktop = play_screenshot(frame.string(), "--rgbd --depthiness 2 --gl desktop", "rgbd-desktop");
  std::string output;
  const ImageF shown = play_screenshot(frame.string(), "--rgbd --depthiness 2 " + extra(), tag("rgbd"), &output,
                                       GetParam().env);
  expect_es(output);
  ASSERT_FALSE(shown.empty());
  ASSERT_FALSE(desktop.empty());
  EXPECT_GE(render::psnr(shown, desktop), 40.0);
}

INSTANTIATE_TEST_SUITE_P(Flavours, PlayWindowOnOpenGlEs,
                         testing::Values(GlFlavour{"es", "", "--gl es"}, GlFlavour{"env", "LFD_GL=es ", ""},
                                         GlFlavour{"capped", "MESA_GL_VERSION_OVERRIDE=3.1 ", ""}),
                         [](const testing::TestParamInfo<GlFlavour>& info) { return std::string(info.param.name); });

// What needs desktop GL 4.5: `lfd view` (Gaussian rendering) on a capped context is one line, exit 2.
TEST(PlayWindow, ViewOnACappedContextIsOneLineExit2) {
  const std::string scene = std::string(LFD_SOURCE_DIR) + "/data/scenes/demo.ply";
  for (const std::string env : {"MESA_GL_VERSION_OVERRIDE=3.1 ", "LFD_GL=es "}) {
    SCOPED_TRACE(env);
    const auto r = test::run_command(env + LFD_EXE + " view " + scene + " --calibration " + kCalibration +
                                     " --simulated --frames 2");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_NE(r.output.find("needs desktop OpenGL 4.5"), std::string::npos) << r.output;
  }
}

// The one-line errors: exit 2 naming the file.
void expect_bad_file(const fs::path& file) {
  const auto r = run_lfd("play " + file.string() + " --calibration " + kCalibration + " --frames 2");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(file.string()), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
}

TEST(PlayWindow, TruncatedVideoIsOneLineExit2) {
  const fs::path video = write_quilt_video("video", layout(8, 6, 48, 64, 0.75), 12);
  const fs::path cut = kDir / ("cut" + render::quilt_suffix(8, 6, 0.75) + ".mp4");
  std::ifstream in(video, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  std::ofstream(cut, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 2));
  expect_bad_file(cut);
}

TEST(PlayWindow, LyingQuiltNameIsOneLineExit2) {
  const render::QuiltLayout real = layout(8, 6, 96, 128, 0.75);
  const fs::path lying = kDir / "lying_qs64x2a0.75.png";
  fs::create_directories(kDir);
  write_png(lying, media::synthetic_quilt(real));
  expect_bad_file(lying);
}

TEST(PlayWindow, NotAVideoIsOneLineExit2) {
  fs::create_directories(kDir);
  const fs::path junk = kDir / "junk_qs8x6a0.75.mp4";
  std::ofstream(junk) << "this is not a video at all, just some text to decode";
  expect_bad_file(junk);
}

// An image shorter than a frame restarts (loops) at every frame: each frame still shows it, no
// black frame while the entry gives way to the next (here itself). Also what keeps frames that
// take seconds (llvmpipe under qemu-user, docs/arm.md) on the picture.
TEST(PlayWindow, ALoopingImageShowsNoBlackFrameAtItsRestart) {
  const fs::path quilt = write_quilt_png("image", layout(8, 6, 96, 128, 0.75));
  const ImageF shown = play_screenshot(quilt.string(), "--duration 0.001", "restart");
  ASSERT_FALSE(shown.empty());
  EXPECT_GE(render::psnr(shown, interlace_reference(quilt)), 40.0);
}

TEST(PlayWindow, PlaylistSkipsBadEntryWithNotice) {
  const fs::path good = write_quilt_png("image", layout(8, 6, 96, 128, 0.75));
  const fs::path junk = kDir / "junk_qs8x6a0.75.mp4";
  std::ofstream(junk) << "not a video";
  const fs::path list = kDir / "playlist.json";
  std::ofstream(list) << R"({"loop": true, "entries": [{"file": ")" << junk.filename().string()
                      << R"("}, {"file": ")" << good.filename().string() << R"(", "duration": 5}]})";
  std::string output;
  const ImageF shown = play_screenshot(list.string(), "", "playlist", &output);
  EXPECT_NE(output.find("notice: skipped: " + junk.string()), std::string::npos) << output;
  ASSERT_FALSE(shown.empty());
  EXPECT_GE(render::psnr(shown, interlace_reference(good)), 40.0);
}

}  // namespace
}  // namespace lfd
