#pragma once
// The library's state between calls (docs/bridge-inproc.md): whether initialize_bridge ran, the
// displays it found, the windows by handle, and the drawing thread. The C functions
// (bridge_exports.cpp) only check pointers and call this; every member throws BadCall (or
// InputError) for a call it refuses, which the C layer turns into false and a log line.
// Thread-safe: one mutex guards the state; GL work goes to the drawing thread.
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "bridge_inproc/bridge_displays.hpp"
#include "bridge_inproc/bridge_window.hpp"
#include "bridge_inproc/caller_texture.hpp"
#include "bridge_inproc/gl_thread.hpp"
#include "render/quilt_layout.hpp"
#include "rgbd/rgbd_options.hpp"

namespace lfd::bridge {

// What a client passed to set_interop_quilt_texture_gl, kept for the window.
struct QuiltTextureSettings {
  unsigned long long texture = 0;
  unsigned format = 0;
  render::QuiltLayout layout;
  double zoom = 1;
};

// What the client sees of a window; the drawing resources live on the drawing thread.
struct WindowRecord {
  std::optional<unsigned long> display_index;  // none: an offscreen window from a calibration file
  BridgeDisplay display;
  WindowPlacement placement;
  bool offscreen = false;
  std::optional<QuiltTextureSettings> quilt_texture;
  unsigned caller_panel_texture = 0;  // get_offscreen_window_texture_gl's, in the caller's context
  std::shared_ptr<BridgeWindow> gl;   // used on the drawing thread only
};

class Runtime {
 public:
  static Runtime& instance();

  void initialize(const std::string& app_name);
  void uninitialize();

  std::vector<unsigned long> display_indices() const;
  // 0xFFFFFFFF (in the low 32 bits) is the first display.
  BridgeDisplay display(unsigned long index) const;
  unsigned long resolve_display_index(unsigned long index) const;
  // The desktop position of a display's monitor (0, 0 when it is not connected).
  std::pair<long, long> display_position(unsigned long index);

  unsigned long make_window(unsigned long display_index, bool offscreen);
  unsigned long make_offscreen_window(int width, int height, const std::string& calibration_path);
  WindowRecord window(unsigned long handle) const;  // a copy
  void set_quilt_texture(unsigned long handle, const QuiltTextureSettings& settings);
  // Posts a frame; returns once `pixels` were handed over.
  void draw_quilt(unsigned long handle, RgbaPixels pixels, const render::QuiltLayout& layout, double zoom);
  void draw_rgbd(unsigned long handle, RgbaPixels pixels, const rgbd::RgbdOptions& options,
                 const render::QuiltLayout& layout);
  void show(unsigned long handle, bool visible);
  // Waits for the frames posted so far, then reads the panel.
  RgbaPixels read_panel(unsigned long handle);
  void set_caller_panel_texture(unsigned long handle, unsigned texture);
  // Frame buffers go round: the caller's copy takes one, the drawing thread gives it back.
  std::vector<uint8_t> take_buffer();
  void give_back_buffer(std::vector<uint8_t> buffer);

 private:
  Runtime() = default;
  void require_initialized() const;
  std::shared_ptr<BridgeWindow> gl_window(unsigned long handle) const;
  unsigned long add_window(WindowRecord record);
  // On the drawing thread: the window, its GL said in the log (the ES fallback notice on stderr).
  std::shared_ptr<BridgeWindow> open_window(const gpu::GlfwSession* session, const BridgeDisplay& display,
                                            const std::string& call);

  mutable std::mutex mutex_;
  bool initialized_ = false;
  std::string app_name_;
  gpu::GlRequest gl_request_ = gpu::GlRequest::kAuto;  // lfd's settings' "gl", LFD_GL over it
  bool es_notice_given_ = false;  // the ES fallback notice, once per initialize (drawing thread)
  std::vector<BridgeDisplay> displays_;
  std::map<unsigned long, WindowRecord> windows_;
  unsigned long next_handle_ = 1;
  std::unique_ptr<GlThread> gl_thread_;
  std::unique_ptr<gpu::GlfwSession> glfw_;  // made and ended on the drawing thread
  std::mutex buffers_mutex_;
  std::vector<std::vector<uint8_t>> buffers_;
};

}  // namespace lfd::bridge
