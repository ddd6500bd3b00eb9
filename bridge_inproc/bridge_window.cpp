#include "bridge_inproc/bridge_window.hpp"

#include <algorithm>
#include <cmath>

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include "display/display_quilt.hpp"
#include "display/lens_model.hpp"

namespace lfd::bridge {

// GLX (a GLFW window) and EGL (offscreen) contexts share this thread: libglvnd lets one API's
// context be current at a time, so each scope releases what it made current.
class BridgeWindow::Current {
 public:
  explicit Current(const BridgeWindow& w) : window_(w) {
    if (w.window_)
      w.window_->make_current();
    else
      w.headless_->make_current();
  }
  ~Current() {
    if (window_.window_)
      glfwMakeContextCurrent(nullptr);
    else
      eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }

 private:
  const BridgeWindow& window_;
};

BridgeWindow::BridgeWindow(const gpu::GlfwSession* session, const display::Calibration& calibration,
                           const std::string& monitor_prefix, gpu::GlRequest gl)
    : calibration_(calibration) {
  const int w = calibration.display.screen_w, h = calibration.display.screen_h;
  placement_.width = w;
  placement_.height = h;
  if (session) {
    GLFWmonitor* monitor = session->display_monitor_or_none(monitor_prefix, w, h);
    window_ = std::make_unique<gpu::DisplayWindow>(*session, monitor, w, h, std::max(w, h), gl);
    desktop_unavailable_ = window_->desktop_unavailable();
    placement_.on_display = window_->on_display();
    glfwGetWindowPos(window_->handle(), &placement_.x, &placement_.y);
    glfwSetWindowTitle(window_->handle(), "lfd bridge");
  } else {
    headless_ = std::make_unique<gpu::HeadlessContext>(gl);
    desktop_unavailable_ = headless_->info().desktop_unavailable;
  }
  Current current(*this);
  gl_summary_ = gpu::query_gl_info(window_ ? "GLFW window" : "EGL headless").summary();
  if (gpu::current_gl_is_es()) gl_summary_ += " [OpenGL ES path]";
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &placement_.max_texture_size);
  panel_ = gpu::Texture(GL_RGBA8, w, h);
  const std::vector<uint8_t> black(size_t(w) * h * 4, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gpu::upload_texture_2d(panel_, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, black.data());
}

BridgeWindow::~BridgeWindow() {
  Current current(*this);
  rgbd_views_.reset();
  interlacer_.reset();
  quilt_ = {};
  frame_ = {};
  panel_ = {};
}

void BridgeWindow::upload(gpu::Texture& texture, const RgbaPixels& pixels) {
  if (texture.width() != pixels.width || texture.height() != pixels.height)
    texture = gpu::Texture(GL_RGBA8, pixels.width, pixels.height);
  texture.set_filter(GL_LINEAR);
  gpu::upload_texture_2d(texture, 0, 0, pixels.width, pixels.height, GL_RGBA, GL_UNSIGNED_BYTE,
                         pixels.bytes.data());
}

void BridgeWindow::interlace_and_show(const render::QuiltLayout& layout) {
  const auto same = [](const render::QuiltLayout& a, const render::QuiltLayout& b) {
    return a.cols == b.cols && a.rows == b.rows && a.views == b.views && a.aspect == b.aspect &&
           a.width == b.width && a.height == b.height;
  };
  if (!interlacer_ || !same(layout, interlacer_layout_)) {
    interlacer_ = std::make_unique<gpu::GlInterlacer>(display::LensModel(calibration_.display, calibration_.correction),
                                                      layout, interlace::InterlaceOptions{},
                                                      gpu::InterlacePass::kFragment);
    interlacer_layout_ = layout;
  }
  interlacer_->interlace(quilt_, panel_);
  if (window_) {
    window_->draw(panel_);
    window_->swap();
  } else {
    glFlush();
  }
}

void BridgeWindow::draw_quilt(RgbaPixels& quilt, const render::QuiltLayout& layout, double zoom) {
  if (zoom != 1.0) zoom_views(quilt, layout, zoom);
  Current current(*this);
  upload(quilt_, quilt);
  interlace_and_show(layout);
}

void BridgeWindow::draw_rgbd(const RgbaPixels& frame, const rgbd::RgbdOptions& options,
                             const render::QuiltLayout& layout) {
  Current current(*this);
  upload(frame_, frame);
  if (!rgbd_views_) rgbd_views_ = std::make_unique<rgbd::GlRgbdViews>();
  if (quilt_.width() != layout.width || quilt_.height() != layout.height)
    quilt_ = gpu::Texture(GL_RGBA8, layout.width, layout.height);
  rgbd_views_->render(frame_, options, layout, quilt_, display::effective_view_cone_deg(calibration_));
  interlace_and_show(layout);
}

void BridgeWindow::set_visible(bool visible) {
  if (!window_) return;  // an offscreen window has nothing to show
  Current current(*this);
  window_->set_visible(visible);
}

RgbaPixels BridgeWindow::read_panel() {
  Current current(*this);
  RgbaPixels out;
  out.width = panel_.width();
  out.height = panel_.height();
  // Read as floats (both GLs have the wrapper); an RGBA8 texel's k/255 comes back to k exactly.
  const std::vector<float> texels = gpu::read_texture_rgba(panel_);
  out.bytes.resize(texels.size());
  for (size_t i = 0; i < texels.size(); ++i)
    out.bytes[i] = uint8_t(std::lround(std::clamp(texels[i], 0.0f, 1.0f) * 255.0f));
  return out;
}

void zoom_views(RgbaPixels& quilt, const render::QuiltLayout& layout, double zoom) {
  const int tw = layout.tile_width(), th = layout.tile_height();
  const RgbaPixels source = quilt;
  for (int view = 0; view < layout.cols * layout.rows; ++view) {
    const int x0 = (view % layout.cols) * tw, y0 = (view / layout.cols) * th;  // bottom-up rows
    for (int y = 0; y < th; ++y)
      for (int x = 0; x < tw; ++x) {
        // The source point of this pixel centre, about the tile centre.
        const double sx = (x + 0.5 - tw / 2.0) / zoom + tw / 2.0 - 0.5;
        const double sy = (y + 0.5 - th / 2.0) / zoom + th / 2.0 - 0.5;
        uint8_t* out = &quilt.bytes[(size_t(y0 + y) * quilt.width + x0 + x) * 4];
        if (sx < -0.5 || sy < -0.5 || sx > tw - 0.5 || sy > th - 0.5) {
          out[0] = out[1] = out[2] = 0;
          out[3] = 255;
          continue;
        }
        const int ix = std::clamp(int(std::floor(sx)), 0, tw - 1), iy = std::clamp(int(std::floor(sy)), 0, th - 1);
        const int jx = std::min(ix + 1, tw - 1), jy = std::min(iy + 1, th - 1);
        const double fx = std::clamp(sx - ix, 0.0, 1.0), fy = std::clamp(sy - iy, 0.0, 1.0);
        const auto at = [&](int px, int py, int c) {
          return double(source.bytes[(size_t(y0 + py) * source.width + x0 + px) * 4 + c]);
        };
        for (int c = 0; c < 4; ++c) {
          const double v = (at(ix, iy, c) * (1 - fx) + at(jx, iy, c) * fx) * (1 - fy) +
                           (at(ix, jy, c) * (1 - fx) + at(jx, jy, c) * fx) * fy;
          out[c] = uint8_t(std::lround(std::clamp(v, 0.0, 255.0)));
        }
      }
  }
}

}  // namespace lfd::bridge
