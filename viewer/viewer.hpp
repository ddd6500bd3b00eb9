#pragma once
// `lfd view`: the real-time viewer. The display window shows the interlaced frame every vsync
// on the display's monitor (or a simulated display in a window when none is connected); the
// control window (Dear ImGui) edits the renderer and the camera. Scripted runs
// (`frames > 0`) render that many frames and write the screenshot, quilt and camera asked for.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "display/calibration_file.hpp"
#include "gpu/gl/raster_path.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"
#include "viewer/viewer_settings.hpp"

namespace lfd::viewer {

// A quilt video of the frames shown (docs/viewer.md "Recording"): the V key starts and stops one,
// `--record` records a scripted run. The program supplies the writer (apps/view.cpp: lfd
// record's video file), as the viewer sits below the encoder's layers.
class QuiltRecording {
 public:
  virtual ~QuiltRecording() = default;
  // One shown frame's quilt (RGB, top-down, the layout the recording started with).
  virtual void add(const Image8& quilt) = 0;
  // Closes the video; returns the file written.
  virtual std::filesystem::path finish() = 0;
};
// Starts a recording of quilts of `layout` into `path` (a name without the tiling: the writer adds it).
using StartRecording =
    std::function<std::unique_ptr<QuiltRecording>(const render::QuiltLayout& layout, const std::filesystem::path& path)>;

struct ViewerOptions {
  std::filesystem::path scene_path;  // a scene, or a moving one (scene/scene_sequence.hpp)
  double scene_fps = 24.0;           // a moving scene's frames per second (scripted runs: one per frame)
  int frames_ahead = 3;              // a moving scene's frames read ahead (memory: this + 1 frames)
  display::Calibration calibration;
  std::string display_name;          // for messages and the settings file's name
  std::string monitor_prefix = "LKG";
  bool simulated_display = false;    // a window even when the display's monitor is there
  bool controls = true;              // the control window
  std::optional<Method> method;      // overrides the saved settings
  std::optional<std::filesystem::path> camera_path;  // cam.json to start from
  std::optional<std::filesystem::path> settings_path;  // default: per display (viewer_settings.hpp)
  int frames = 0;                    // 0: until the window is closed
  bool vsync = true;                 // false: swap interval 0 (measuring the frame, --no-vsync)
  gpu::RasterPath raster = gpu::RasterPath::kHardware;  // --raster (docs/gpu.md)
  std::filesystem::path screenshot_path, quilt_path, camera_out_path;  // written after the last frame
  StartRecording start_recording;      // null: no recording (the V key says so)
  std::filesystem::path record_path;   // a scripted run records every frame into this video
};

// Runs the viewer; returns the exit code. Bad input throws InputError (exit 2).
int run_viewer(const ViewerOptions& options);

}  // namespace lfd::viewer
