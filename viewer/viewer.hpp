#pragma once
// `lfd view`: the real-time viewer. The display window shows the interlaced frame every vsync
// on the display's monitor (or a simulated display in a window when none is connected); the
// control window (Dear ImGui) edits the renderer and the camera. Scripted runs
// (`frames > 0`) render that many frames and write the screenshot, quilt and camera asked for.
#include <filesystem>
#include <optional>
#include <string>

#include "display/calibration_file.hpp"
#include "gpu/raster_path.hpp"
#include "viewer/viewer_settings.hpp"

namespace lfd::viewer {

struct ViewerOptions {
  std::filesystem::path scene_path;
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
};

// Runs the viewer; returns the exit code. Bad input throws InputError (exit 2).
int run_viewer(const ViewerOptions& options);

}  // namespace lfd::viewer
