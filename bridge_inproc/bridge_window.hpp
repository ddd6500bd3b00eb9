#pragma once
// One Bridge window on the drawing thread (docs/bridge-inproc.md "What it draws"): the unit's
// panel interlaced by gpu::GlInterlacer from a quilt (or from an RGB-D frame through
// rgbd::GlRgbdViews), shown full screen on the unit's monitor, in a window of the panel's size
// when that monitor is not connected (the simulated display), or kept in a texture only (an
// offscreen window, on a headless EGL context). Every member runs on the drawing thread.
#include <memory>

#include "bridge_inproc/caller_texture.hpp"
#include "display/calibration_file.hpp"
#include "gpu/gl/display_window.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/gl/glfw_session.hpp"
#include "gpu/panel/gl_interlacer.hpp"
#include "render/quilt_layout.hpp"
#include "rgbd/gl_rgbd_views.hpp"
#include "rgbd/rgbd_options.hpp"

namespace lfd::bridge {

struct WindowPlacement {
  int width = 0, height = 0;  // the panel's
  int x = 0, y = 0;           // on the desktop (0, 0 offscreen)
  int max_texture_size = 0;
  bool on_display = false;    // full screen on the unit's monitor
};

class BridgeWindow {
 public:
  // `session` null: an offscreen window. InputError when no GL context or window can be made.
  // `gl`: the OpenGL of its context (docs/arm.md): desktop 4.5, ES 3.1, or auto (desktop, else ES).
  BridgeWindow(const gpu::GlfwSession* session, const display::Calibration& calibration,
               const std::string& monitor_prefix, gpu::GlRequest gl);
  ~BridgeWindow();
  BridgeWindow(const BridgeWindow&) = delete;
  BridgeWindow& operator=(const BridgeWindow&) = delete;

  const WindowPlacement& placement() const { return placement_; }
  // Which GL the context speaks ("llvmpipe (...) (OpenGL ES 3.2 Mesa ...) [OpenGL ES path]"), and
  // why desktop OpenGL 4.5 could not be made when auto took ES ("" otherwise).
  const std::string& gl_summary() const { return gl_summary_; }
  const std::string& desktop_unavailable() const { return desktop_unavailable_; }

  // `quilt`: RGBA8, rows bottom-up, of layout.width x layout.height. `zoom` != 1 magnifies (or
  // shrinks) each view about its centre first.
  void draw_quilt(RgbaPixels& quilt, const render::QuiltLayout& layout, double zoom);
  // `frame`: the side-by-side RGB-D picture, RGBA8 rows bottom-up; the views go into a quilt of
  // `layout`, then as draw_quilt.
  void draw_rgbd(const RgbaPixels& frame, const rgbd::RgbdOptions& options, const render::QuiltLayout& layout);
  void set_visible(bool visible);
  // The last panel drawn (black before the first), RGBA8 rows bottom-up.
  RgbaPixels read_panel();

 private:
  class Current;  // makes the context current for a scope and releases it after
  void interlace_and_show(const render::QuiltLayout& layout);
  void upload(gpu::Texture& texture, const RgbaPixels& pixels);

  display::Calibration calibration_;
  std::unique_ptr<gpu::DisplayWindow> window_;
  std::unique_ptr<gpu::HeadlessContext> headless_;
  WindowPlacement placement_;
  std::string gl_summary_, desktop_unavailable_;
  std::unique_ptr<gpu::GlInterlacer> interlacer_;
  render::QuiltLayout interlacer_layout_;
  std::unique_ptr<rgbd::GlRgbdViews> rgbd_views_;
  gpu::Texture quilt_, frame_, panel_;
};

// Each view of a bottom-up RGBA8 quilt magnified by `zoom` about its centre (bilinear; black
// where a zoom below 1 leaves the view), in place.
void zoom_views(RgbaPixels& quilt, const render::QuiltLayout& layout, double zoom);

}  // namespace lfd::bridge
