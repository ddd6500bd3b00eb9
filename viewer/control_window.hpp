#pragma once
// The viewer's control window (Dear ImGui, on the main monitor): frame time per stage, the G2LF
// and quilt parameters, a quilt preview, and the buttons that save a screenshot, the quilt,
// cam.json and the settings. It shares the display window's GL objects.
#include <optional>
#include <string>
#include <vector>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/glfw_session.hpp"
#include "viewer/seen_from_preview.hpp"
#include "viewer/viewer_settings.hpp"

struct GLFWwindow;

namespace lfd::viewer {

// What the last frame cost and what it showed (read by the control window).
struct FrameReport {
  double frame_seconds = 0;      // wall clock between frames: median of the recent ones
  double frame_p99_seconds = 0;  // and their 99th percentile (viewer/frame_pacing.hpp)
  double binning_seconds = 0, planes_seconds = 0, swizzle_seconds = 0;  // G2LF stages (GPU)
  double raster_seconds = 0;      // per view: preprocess + sort + draw of every view (GPU)
  double interlace_seconds = 0;   // GPU
  size_t plane_bytes = 0, gpu_peak_bytes = 0;
  int views = 0, cols = 0, rows = 0, view_width = 0, view_height = 0;
  double view_cone_deg = 0;
  std::string renderer;  // GlInfo-like summary
  std::string display;   // the display's name and where its calibration came from
  std::vector<std::string> fit_notices;  // what was lowered to fit (SH degree, plane precision)
};

// The "seen from" preview's controls (not remembered per display: where one looks from is not
// a setting of the display).
struct SeenFromControls {
  bool visible = true;
  SeenFromEye eye;
};

// The images the control window shows, made in the display window's (shared) context.
struct ControlImages {
  const gpu::Texture* quilt = nullptr;
  const gpu::Texture* seen_from = nullptr;
  double seen_from_age_s = -1;  // since the preview was computed; < 0: not yet
  double seen_from_cost_s = 0;  // what computing it took (read-back + optics)
};

// Buttons pressed this frame.
struct ControlActions {
  bool screenshot = false, save_quilt = false, save_camera = false, save_settings = false;
  bool reset_camera = false;
};

class ControlWindow {
 public:
  // Shares `share`'s GL objects (textures) so the quilt preview draws directly.
  ControlWindow(const gpu::GlfwSession& session, GLFWwindow* share);
  ~ControlWindow();
  ControlWindow(const ControlWindow&) = delete;
  ControlWindow& operator=(const ControlWindow&) = delete;

  GLFWwindow* handle() const { return window_; }
  // Puts the window to the right of `other` (a simulated display window on the same desktop).
  void place_beside(GLFWwindow* other);
  bool should_close() const;
  // One ImGui frame: edits `settings` and `seen_from`; shows the images scaled. Returns the
  // buttons pressed. Makes `restore` (the display window's context) current again.
  ControlActions draw(ViewerSettings& settings, SeenFromControls& seen_from, const FrameReport& report,
                      const ControlImages& images, GLFWwindow* restore);
  // One frame with only `what` and a progress bar (`fraction` in [0, 1]), between the pieces of
  // a long upload, so the window stays alive and says what it waits for.
  void draw_progress(const std::string& what, double fraction, GLFWwindow* restore);
  // Whether ImGui wants the mouse/keyboard (then the camera controls leave them alone).
  bool wants_mouse() const;
  bool wants_keyboard() const;

 private:
  void begin_frame();
  void end_frame(GLFWwindow* restore);

  GLFWwindow* window_ = nullptr;
  void* imgui_context_ = nullptr;
};

}  // namespace lfd::viewer
