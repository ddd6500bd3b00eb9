#include "bridge_inproc/bridge_runtime.hpp"

#include <utility>

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "bridge_inproc/bridge_log.hpp"
#include "bridge_inproc/bridge_settings.hpp"

namespace lfd::bridge {

namespace {
constexpr unsigned long kFirstDisplay = 0xFFFFFFFFul;
}

Runtime& Runtime::instance() {
  // Never destroyed: at process exit a client may already have ended GLFW or its contexts, so the
  // windows and the drawing thread are left to the exit rather than torn down then.
  static Runtime* runtime = new Runtime;
  return *runtime;
}

void Runtime::require_initialized() const {
  if (!initialized_) refuse("initialize_bridge has not been called");
}

void Runtime::initialize(const std::string& app_name) {
  std::lock_guard lock(mutex_);
  if (initialized_) return;  // a second call changes nothing, as Bridge's
  const std::filesystem::path settings_path = lfd_settings_path();
  const LfdBridgeSettings settings = read_lfd_settings(settings_path);
  gl_request_ = library_gl_request(settings);
  es_notice_given_ = false;
  displays_ = find_displays(settings);
  app_name_ = app_name;
  gl_thread_ = std::make_unique<GlThread>();
  initialized_ = true;
}

void Runtime::uninitialize() {
  std::unique_ptr<GlThread> thread;
  std::map<unsigned long, WindowRecord> windows;
  {
    std::lock_guard lock(mutex_);
    if (!initialized_) return;
    initialized_ = false;
    windows.swap(windows_);
    displays_.clear();
    thread = std::move(gl_thread_);
  }
  // Windows and GLFW end on the thread that made them.
  thread->call([&] {
    for (auto& [handle, record] : windows) record.gl.reset();
    glfw_.reset();
  });
  thread.reset();
}

std::vector<unsigned long> Runtime::display_indices() const {
  std::lock_guard lock(mutex_);
  require_initialized();
  std::vector<unsigned long> out;
  for (size_t i = 0; i < displays_.size(); ++i) out.push_back(i);
  return out;
}

unsigned long Runtime::resolve_display_index(unsigned long index) const {
  index &= 0xFFFFFFFFul;  // the Python SDK passes 32 bits, bridge.h's callers 64
  if (index == kFirstDisplay) {
    if (displays_.empty())
      refuse("no display: none was registered (lfd bridge register) and device discovery found no Looking Glass");
    return 0;
  }
  if (index >= displays_.size())
    refuse(fmt::format("display index {}: there are {} displays", index, displays_.size()));
  return index;
}

BridgeDisplay Runtime::display(unsigned long index) const {
  std::lock_guard lock(mutex_);
  require_initialized();
  return displays_[resolve_display_index(index)];
}

std::pair<long, long> Runtime::display_position(unsigned long index) {
  BridgeDisplay d;
  GlThread* thread = nullptr;
  {
    std::lock_guard lock(mutex_);
    require_initialized();
    const unsigned long i = resolve_display_index(index);
    d = displays_[i];
    for (const auto& [handle, record] : windows_)
      if (record.display_index == i && !record.offscreen) return {record.placement.x, record.placement.y};
    thread = gl_thread_.get();
  }
  // No window on it yet: where its monitor is, when connected.
  return thread->call([&]() -> std::pair<long, long> {
    try {
      if (!glfw_) glfw_ = std::make_unique<gpu::GlfwSession>();
      GLFWmonitor* monitor = glfw_->find_display_monitor(d.monitor_prefix, d.calibration.display.screen_w,
                                                         d.calibration.display.screen_h);
      int x = 0, y = 0;
      glfwGetMonitorPos(monitor, &x, &y);
      return {x, y};
    } catch (const std::exception&) {
      return {0, 0};
    }
  });
}

unsigned long Runtime::add_window(WindowRecord record) {
  std::lock_guard lock(mutex_);
  require_initialized();
  const unsigned long handle = next_handle_++;
  windows_[handle] = std::move(record);
  return handle;
}

unsigned long Runtime::make_window(unsigned long display_index, bool offscreen) {
  WindowRecord record;
  GlThread* thread = nullptr;
  {
    std::lock_guard lock(mutex_);
    require_initialized();
    const unsigned long i = resolve_display_index(display_index);
    record.display_index = i;
    record.display = displays_[i];
    record.offscreen = offscreen;
    thread = gl_thread_.get();
  }
  record.gl = thread->call([&] {
    if (!offscreen && !glfw_)
      glfw_ = std::make_unique<gpu::GlfwSession>("the Bridge window needs the desktop session the display is on");
    return open_window(offscreen ? nullptr : glfw_.get(), record.display,
                       offscreen ? "instance_offscreen_window_gl" : "instance_window_gl");
  });
  record.placement = record.gl->placement();
  return add_window(std::move(record));
}

unsigned long Runtime::make_offscreen_window(int width, int height, const std::string& calibration_path) {
  if (width <= 0 || height <= 0) refuse(fmt::format("size {}x{}", width, height));
  WindowRecord record;
  record.display = bridge_display_of(display::read_calibration(calibration_path), calibration_path);
  // The panel at the size asked for: the same physical screen, resampled (docs/bridge-inproc.md).
  display::DisplayCalibration& panel = record.display.calibration.display;
  panel.dpi *= double(width) / panel.screen_w;
  panel.screen_w = width;
  panel.screen_h = height;
  record.offscreen = true;
  GlThread* thread = nullptr;
  {
    std::lock_guard lock(mutex_);
    require_initialized();
    thread = gl_thread_.get();
  }
  record.gl = thread->call([&] { return open_window(nullptr, record.display, "instance_offscreen_window"); });
  record.placement = record.gl->placement();
  return add_window(std::move(record));
}

std::shared_ptr<BridgeWindow> Runtime::open_window(const gpu::GlfwSession* session, const BridgeDisplay& display,
                                                  const std::string& call) {
  // gl_request_ is set once by initialize, before the drawing thread exists.
  auto window = std::make_shared<BridgeWindow>(session, display.calibration, session ? display.monitor_prefix : "",
                                               gl_request_);
  if (!window->desktop_unavailable().empty() && !std::exchange(es_notice_given_, true))
    log_line(call, gpu::es_fallback_notice(window->desktop_unavailable()));
  log_detail(call, "gl: " + window->gl_summary());
  return window;
}

WindowRecord Runtime::window(unsigned long handle) const {
  std::lock_guard lock(mutex_);
  require_initialized();
  const auto it = windows_.find(handle & 0xFFFFFFFFul);
  if (it == windows_.end()) refuse(fmt::format("window {} is not one of this library's windows", handle));
  return it->second;
}

std::shared_ptr<BridgeWindow> Runtime::gl_window(unsigned long handle) const { return window(handle).gl; }

void Runtime::set_quilt_texture(unsigned long handle, const QuiltTextureSettings& settings) {
  window(handle);  // checks the handle
  std::lock_guard lock(mutex_);
  windows_[handle & 0xFFFFFFFFul].quilt_texture = settings;
}

void Runtime::draw_quilt(unsigned long handle, RgbaPixels pixels, const render::QuiltLayout& layout, double zoom) {
  std::shared_ptr<BridgeWindow> gl = gl_window(handle);
  std::lock_guard lock(mutex_);
  require_initialized();
  gl_thread_->post(handle & 0xFFFFFFFFul, "draw_interop_quilt_texture_gl",
                   [this, gl, layout, zoom, p = std::move(pixels)]() mutable {
                     gl->draw_quilt(p, layout, zoom);
                     give_back_buffer(std::move(p.bytes));
                   });
}

void Runtime::draw_rgbd(unsigned long handle, RgbaPixels pixels, const rgbd::RgbdOptions& options,
                        const render::QuiltLayout& layout) {
  std::shared_ptr<BridgeWindow> gl = gl_window(handle);
  std::lock_guard lock(mutex_);
  require_initialized();
  gl_thread_->post(handle & 0xFFFFFFFFul, "draw_interop_rgbd_texture_gl",
                   [this, gl, options, layout, p = std::move(pixels)]() mutable {
                     gl->draw_rgbd(p, options, layout);
                     give_back_buffer(std::move(p.bytes));
                   });
}

void Runtime::show(unsigned long handle, bool visible) {
  std::shared_ptr<BridgeWindow> gl = gl_window(handle);
  std::lock_guard lock(mutex_);
  require_initialized();
  gl_thread_->post(0, "show_window", [gl, visible] { gl->set_visible(visible); });
}

RgbaPixels Runtime::read_panel(unsigned long handle) {
  std::shared_ptr<BridgeWindow> gl = gl_window(handle);
  GlThread* thread = nullptr;
  {
    std::lock_guard lock(mutex_);
    require_initialized();
    thread = gl_thread_.get();
  }
  // Queued behind the frames already posted, so it reads the newest.
  return thread->call([gl] { return gl->read_panel(); });
}

void Runtime::set_caller_panel_texture(unsigned long handle, unsigned texture) {
  window(handle);
  std::lock_guard lock(mutex_);
  windows_[handle & 0xFFFFFFFFul].caller_panel_texture = texture;
}

std::vector<uint8_t> Runtime::take_buffer() {
  std::lock_guard lock(buffers_mutex_);
  if (buffers_.empty()) return {};
  std::vector<uint8_t> b = std::move(buffers_.back());
  buffers_.pop_back();
  return b;
}

void Runtime::give_back_buffer(std::vector<uint8_t> buffer) {
  std::lock_guard lock(buffers_mutex_);
  if (buffers_.size() < 4) buffers_.push_back(std::move(buffer));  // a frame in each hand, and spares
}

}  // namespace lfd::bridge
