// `lfd view` in a real GLFW window under Xvfb: the window's screenshot equals the headless EGL
// render of the same camera and settings; the control state (N_chunk, focal distance) changes
// the frame measurably; bad input is one line.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "gpu/gl/gl_context.hpp"
#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "render/image_metrics.hpp"
#include "scene/ply_writer.hpp"
#include "render/scene_generator.hpp"
#include "tests/support/scene_fixtures.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "viewer/light_field_frame.hpp"
#include "viewer/viewer.hpp"

namespace lfd::viewer {
namespace {

namespace fs = std::filesystem;

const fs::path kDir = fs::temp_directory_path() / "lfd_viewer_window_test";

scene::GaussianScene test_scene() { return test::generated_gaussians(3000, 1); }

// Small quilts so llvmpipe keeps up: 8 views of 96 px height.
ViewerSettings small_settings() {
  ViewerSettings s;
  s.views = 8;
  s.view_height_px = 96;
  s.g2lf.chunks = 16;
  return s;
}

struct Files {
  fs::path scene, settings, camera, screenshot;
};

Files write_inputs(const ViewerSettings& s, const std::string& tag) {
  fs::create_directories(kDir);
  Files f;
  f.scene = kDir / "scene.ply";
  // Written every time: a scene left in the temporary folder by another build (another generator)
  // would not be the one the headless render draws.
  write_text_atomic(f.scene, scene::encode_ply(test_scene()));
  f.settings = kDir / (tag + ".settings.json");
  save_settings(f.settings, s);
  f.camera = kDir / "cam.json";
  write_text_atomic(f.camera, render::camera_json_text(render::frame_scene(test_scene())));
  f.screenshot = kDir / (tag + ".png");
  fs::remove(f.screenshot);
  return f;
}

ViewerOptions scripted(const Files& f) {
  ViewerOptions o;
  o.scene_path = f.scene;
  // The Xvfb screen is this panel's size (CMakeLists.txt), so the viewer finds its "monitor".
  o.calibration = test::portrait_calibration();
  o.display_name = "LKG-PORT-portrait (test)";
  o.camera_path = f.camera;
  o.settings_path = f.settings;
  o.frames = 3;
  o.screenshot_path = f.screenshot;
  return o;
}

ImageF headless_panel(const ViewerSettings& s) {
  gpu::HeadlessContext context;
  LightFieldFrame frame(test_scene(), test::portrait_calibration(), context.info());
  frame.render(render::frame_scene(test_scene()), s);
  return gpu::image_from_texture(frame.panel());
}

TEST(ViewerWindow, TheWindowShowsTheHeadlessRenderOnTheDisplaysMonitor) {
  for (Method method : {Method::kG2lf, Method::kPerView}) {
    ViewerSettings s = small_settings();
    s.method = method;
    const Files f = write_inputs(s, "same-" + method_name(method));
    const ImageF expected = headless_panel(s);
    ASSERT_EQ(run_viewer(scripted(f)), 0);
    const Image8 shown = read_image(f.screenshot);
    ASSERT_EQ(shown.width, 1536);  // the panel 1:1: the window is on the display's monitor
    ASSERT_EQ(shown.height, 2048);
    const double psnr = render::psnr(to_float(shown), expected);
    EXPECT_GE(psnr, 40.0) << method_name(method);
  }
}

TEST(ViewerWindow, ControlStateChangesTheFrame) {
  ViewerSettings base = small_settings();
  ViewerSettings fewer_chunks = base;
  fewer_chunks.g2lf.chunks = 2;
  ViewerSettings nearer_focus = base;
  nearer_focus.focal_fraction = 0.5f;
  auto shot = [](const ViewerSettings& s, const std::string& tag) {
    const Files f = write_inputs(s, tag);
    EXPECT_EQ(run_viewer(scripted(f)), 0);
    return to_float(read_image(f.screenshot));
  };
  const ImageF a = shot(base, "base"), b = shot(fewer_chunks, "chunks"), c = shot(nearer_focus, "focus");
  EXPECT_LT(render::psnr(a, b), 40.0) << "N_chunk 16 -> 2 left the frame unchanged";
  EXPECT_LT(render::psnr(a, c), 40.0) << "moving the focal plane left the frame unchanged";
}

// A recording that keeps what it is given (the program's writer is lfd record's video file).
struct KeptRecording : QuiltRecording {
  std::vector<Image8>* quilts;
  int* finished;
  KeptRecording(std::vector<Image8>* q, int* f) : quilts(q), finished(f) {}
  void add(const Image8& quilt) override { quilts->push_back(quilt); }
  std::filesystem::path finish() override {
    ++*finished;
    return "kept.mp4";
  }
};

TEST(ViewerWindow, ARecordingGetsEveryShownFramesQuilt) {
  const ViewerSettings s = small_settings();
  const Files f = write_inputs(s, "record");
  ViewerOptions o = scripted(f);
  o.quilt_path = kDir / "record-quilt.png";
  o.record_path = kDir / "shown.mp4";
  std::vector<Image8> quilts;
  int finished = 0;
  render::QuiltLayout started;
  o.start_recording = [&](const render::QuiltLayout& layout, const std::filesystem::path& path) {
    started = layout;
    EXPECT_EQ(path, kDir / "shown.mp4");
    return std::make_unique<KeptRecording>(&quilts, &finished);
  };
  ASSERT_EQ(run_viewer(o), 0);
  EXPECT_EQ(finished, 1);
  ASSERT_EQ(quilts.size(), 3u) << "one quilt per frame shown";
  EXPECT_EQ(quilts[0].width, started.width);
  EXPECT_EQ(quilts[0].height, started.height);
  // The last one is the quilt the run writes after its last frame.
  for (const auto& e : fs::directory_iterator(kDir))
    if (e.path().filename().string().starts_with("record-quilt_qs"))
      EXPECT_GE(render::psnr(to_float(quilts.back()), to_float(read_image(e.path(), 3))), 60.0);
}

TEST(ViewerWindow, AMovingSceneShowsItsFramesInTurn) {
  // Two frames: the test scene, and the same with red and blue swapped. A scripted run shows one
  // scene frame per frame: the recorded quilts alternate, 0 1 0.
  const ViewerSettings s = small_settings();
  const Files f = write_inputs(s, "moving");
  scene::GaussianScene swapped = test_scene();
  for (size_t i = 0; i < swapped.size(); ++i) std::swap(swapped.sh[i * swapped.sh_coeffs() * 3], swapped.sh[i * swapped.sh_coeffs() * 3 + 2]);
  fs::copy_file(f.scene, kDir / "moving_0000.ply", fs::copy_options::overwrite_existing);
  write_text_atomic(kDir / "moving_0001.ply", scene::encode_ply(swapped));
  ViewerOptions o = scripted(f);
  o.scene_path = kDir / "moving_%04d.ply";
  o.record_path = kDir / "moving.mp4";
  std::vector<Image8> quilts;
  int finished = 0;
  o.start_recording = [&](const render::QuiltLayout&, const std::filesystem::path&) {
    return std::make_unique<KeptRecording>(&quilts, &finished);
  };
  ASSERT_EQ(run_viewer(o), 0);
  ASSERT_EQ(quilts.size(), 3u);
  const auto db = [](const Image8& a, const Image8& b) { return render::psnr(to_float(a), to_float(b)); };
  EXPECT_LT(db(quilts[0], quilts[1]), 30.0) << "frame 1 shows the second scene frame";
  EXPECT_GT(db(quilts[0], quilts[2]), 60.0) << "frame 2 loops back to the first";
}

TEST(ViewerWindow, BadSceneIsOneLineNamingTheFile) {
  const Files f = write_inputs(small_settings(), "bad");
  std::ofstream(kDir / "broken.ply") << "ply\nformat nonsense\n";
  ViewerOptions o = scripted(f);
  o.scene_path = kDir / "broken.ply";
  try {
    run_viewer(o);
    FAIL() << "a broken scene was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.ply"), std::string::npos) << e.what();
  }
}

TEST(ViewerWindow, NoDesktopIsOneLine) {
  const Files f = write_inputs(small_settings(), "nodisplay");
  const std::string display = std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "";
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  try {
    run_viewer(scripted(f));
    ADD_FAILURE() << "the viewer ran without a desktop";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no display"), std::string::npos) << e.what();
  }
  setenv("DISPLAY", display.c_str(), 1);
}

}  // namespace
}  // namespace lfd::viewer
