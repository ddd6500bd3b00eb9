// `lfd view`: the real-time viewer (viewer/viewer.hpp).
//   lfd view scene.ply --device auto
//   lfd view scene.ply --calibration visual.json --monitor LKG
//   lfd view scene.ply --calibration visual.json --frames 30 --screenshot panel.png --quilt q.png
#include <filesystem>
#include <iostream>

#include <fmt/format.h>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_flavour.hpp"
#include "interlace/quilt_file_name.hpp"
#include "util/error.hpp"
#include "viewer/viewer.hpp"
#ifndef LFD_NO_PLAYBACK
#include "record/video_file.hpp"
#endif

namespace lfd::apps {
namespace {

#ifndef LFD_NO_PLAYBACK
// The viewer's recordings as lfd record writes them (record/video_file.hpp): NAME_qsCxRaA.mp4,
// H.264 at `fps`, a partial file until stopped.
class ViewerVideo : public viewer::QuiltRecording {
 public:
  ViewerVideo(const render::QuiltLayout& layout, const std::filesystem::path& path, int fps)
      : file_(interlace::quilt_file_name(path.string(), layout, "--record"), layout.width, layout.height, options(fps)) {}
  void add(const Image8& quilt) override { file_.add(quilt); }
  std::filesystem::path finish() override { return file_.finish(); }

 private:
  static media::EncoderOptions options(int fps) {
    media::EncoderOptions o;
    o.frame_rate = fps;
    return o;
  }
  record::VideoFile file_;
};
#endif

}  // namespace

int RunView(int argc, char** argv) {
  CLI::App app{"Show a Gaussian scene (G2LF or per view) or a sparse-voxel scene (V2LF or per view)\n"
               "on the display in real time: the interlaced frame every vsync, full screen on the display's\n"
               "monitor, with a control window.\n"
               "Without the display's monitor: a simulated display in a window.\n"
               "Mouse: drag orbits, right drag pans, wheel zooms; keys: arrows, WASD, +/-, R resets,\n"
               "V starts and stops a quilt video of the frames shown, Esc quits; drop a scene file on a\n"
               "window to load it.\n"
               "Examples:\n"
               "  lfd view scene.ply --device auto\n"
               "  lfd view scene.ply --calibration visual.json --method per-view\n"
               "  lfd view tabletop.voxels --calibration visual.json\n"
               "  lfd view scene.ply --calibration visual.json --frames 30 --screenshot panel.png --quilt q.png",
               "view"};
  viewer::ViewerOptions options;
  std::string scene, method, camera, settings, screenshot, quilt, camera_out;
  app.add_option("scene", scene,
                 "scene file: Gaussians (.ply, compressed .ply, .splat, .spz) or sparse voxels (.voxels, "
                 "svraster-webgl .ply; --method g2lf renders them with V2LF); a moving scene: name_%04d.ply, a "
                 "folder or a .txt list of frames, played at --scene-fps")->required();
  DisplaySource display_source;
  display_source.add(app, "--calibration", "the display: visual.json or calibration.json");
  app.add_option("--monitor", options.monitor_prefix, "the display's monitor name prefix")->capture_default_str();
  app.add_flag("--simulated", options.simulated_display, "show a simulated display in a window even if the display is connected");
  app.add_option("--method", method, "g2lf, g2lf-direct (no quilt: the panel straight from the planes) or per-view (default: the saved setting, else g2lf)")
      ->check(CLI::IsMember({"g2lf", "g2lf-direct", "per-view"}));
  app.add_option("--camera", camera, "cam.json to start from (default: framing the scene)");
  app.add_option("--settings", settings, "settings file (default: one per display under ~/.config/lfd/viewer)");
  app.add_option("--frames", options.frames, "render this many frames, then write the outputs and quit (0: until closed)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--screenshot", screenshot, "after the last frame: the panel as shown (PNG)");
  app.add_option("--quilt", quilt, "after the last frame: the quilt (PNG; _qs suffix added)");
  app.add_option("--camera-out", camera_out, "after the last frame: the camera as cam.json");
  std::string raster = "hardware";
  add_raster_option(app, raster);
  bool no_controls = false;
  app.add_flag("--no-controls", no_controls, "only the display window");
  bool no_vsync = false;
  app.add_flag("--no-vsync", no_vsync,
               "swap without waiting for vsync (swap interval 0): to measure the frame; a scripted run "
               "prints the frame pacing (median, p99)");
  app.add_option("--scene-fps", options.scene_fps,
                 "a moving scene (name_%04d.ply, a folder or a .txt list of frames): its frames per second")
      ->check(CLI::Range(0.01, 1000.0))->capture_default_str();
  app.add_option("--ahead", options.frames_ahead,
                 "a moving scene: frames read ahead of the one shown (memory holds this many + 1)")
      ->check(CLI::Range(1, 64))->capture_default_str();
  std::string record_path;
  int record_fps = 30;
  app.add_option("--record", record_path,
                 "record the quilts shown into this video from the first frame (NAME.mp4: _qsCxRaA added); "
                 "the V key starts and stops one any time (lfd-view-TIME_qs....mp4)");
  app.add_option("--record-fps", record_fps, "the recordings' frame rate (each shown frame is one video frame)")
      ->check(CLI::Range(1, 240))->capture_default_str();
  if (auto code = parse(app, argc, argv)) return *code;
#ifndef LFD_NO_PLAYBACK
  options.start_recording = [record_fps](const render::QuiltLayout& layout, const std::filesystem::path& path) {
    return std::make_unique<ViewerVideo>(layout, path, record_fps);
  };
#endif
  if (!record_path.empty() && std::filesystem::path(record_path).extension() != ".mp4")
    throw_input_error("--record: '{}' must end in .mp4", record_path);
  options.record_path = record_path;

  options.scene_path = scene;
  options.calibration = display_source.load();
  options.display_name = display_source.name();
  options.controls = !no_controls;
  options.vsync = !no_vsync;
  options.raster = gpu::parse_raster_path(raster);
  if (!method.empty()) options.method = viewer::parse_method(method);
  if (!camera.empty()) options.camera_path = camera;
  if (!settings.empty()) options.settings_path = settings;
  options.screenshot_path = screenshot;
  options.quilt_path = quilt;
  options.camera_out_path = camera_out;
  // The viewer renders Gaussians and voxels: desktop OpenGL 4.5 only (docs/arm.md), said on one line.
  gpu::require_desktop_gl("lfd view");
  try {
    return viewer::run_viewer(options);
  } catch (const gpu::GlUnavailable& e) {
    throw gpu::GlUnavailable(fmt::format("lfd view needs desktop OpenGL 4.5 (OpenGL ES shows quilts only: lfd play; "
                                         "docs/arm.md): {}", e.what()));
  }
}

}  // namespace lfd::apps
