#pragma once
// The viewer's control window (Dear ImGui, on the main monitor): frame time per stage, the G2LF
// and quilt parameters, the camera, a quilt preview and a "seen from" preview, and the buttons
// that save a screenshot, the quilt and cam.json. It shares the display window's GL objects.
#include <optional>
#include <string>

#include "gpu/gl_objects.hpp"
#include "gpu/glfw_session.hpp"
#include "viewer/orbit_camera.hpp"
#include "viewer/viewer_settings.hpp"

struct GLFWwindow;

namespace lfd::viewer {

// What the last frame cost and what it showed (read by the control window).
struct FrameReport {
  double frame_seconds = 0;  // wall clock between frames (median of the last 30)
  double binning_seconds = 0, planes_seconds = 0, swizzle_seconds = 0;  // G2LF stages (GPU)
  double raster_seconds = 0;      // per view: preprocess + sort + draw of every view (GPU)
  double interlace_seconds = 0;   // GPU
  size_t plane_bytes = 0, gpu_peak_bytes = 0;
  int views = 0, cols = 0, rows = 0, view_width = 0, view_height = 0;
  double view_cone_deg = 0;
  std::string renderer;  // GlInfo-like summary
  std::string display;   // the display's name and where its calibration came from
};

// Buttons pressed this frame.
struct ControlActions {
  bool screenshot = false, save_quilt = false, save_camera = false, save_settings = false;
  bool reset_camera = false;
};

class ControlWindow {
 public:
  // Shares `share`'s GL objects (textures) so the quilt and seen-from previews draw directly.
  ControlWindow(const gpu::GlfwSession& session, GLFWwindow* share);
  ~ControlWindow();
  ControlWindow(const ControlWindow&) = delete;
  ControlWindow& operator=(const ControlWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  // One ImGui frame: edits `settings` and `camera`; `quilt` and `seen` (optional) are shown
  // scaled. Returns the buttons pressed. Leaves the display window's context current.
  ControlActions draw(ViewerSettings& settings, OrbitCamera& camera, float& seen_from_deg,
                      const FrameReport& report, const gpu::Texture* quilt,
                      const gpu::Texture* seen, GLFWwindow* restore);
  // Whether ImGui wants the mouse/keyboard (then the camera controls leave them alone).
  bool wants_mouse() const;
  bool wants_keyboard() const;

 private:
  GLFWwindow* window_ = nullptr;
  void* imgui_context_ = nullptr;
};

}  // namespace lfd::viewer
