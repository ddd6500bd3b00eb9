#include "python/script_window.hpp"

#include <chrono>

#include "play/player.hpp"
#include "util/error.hpp"

namespace lfd::python {

struct ScriptWindow::PlayerHolder {
  play::Player player;
};

ScriptWindow::ScriptWindow(ScriptWindowOptions options) {
  window_thread_ = std::thread([this, options = std::move(options)]() mutable { run_window(std::move(options)); });
  std::unique_lock lock(mutex_);
  // Started, and one frame run: on_display() then says where the window went.
  changed_.wait(lock, [this] { return (started_ && (frames_ > 0 || !open_)) || error_; });
  if (error_) {
    lock.unlock();
    window_thread_.join();
    std::rethrow_exception(error_);
  }
  render_thread_ = std::thread([this] { run_renders(); });
}

ScriptWindow::~ScriptWindow() { close(); }

void ScriptWindow::run_window(ScriptWindowOptions options) {
  std::unique_ptr<PlayerHolder> holder;
  try {
    play::PlayerOptions player_options;
    player_options.calibration = std::move(options.calibration);
    player_options.display_name = options.display_name;
    player_options.simulated_display = options.simulated;
    player_options.interlace = options.interlace;
    player_options.print_notices = false;
    holder.reset(new PlayerHolder{play::Player(std::move(player_options))});
  } catch (...) {
    const std::lock_guard lock(mutex_);
    error_ = std::current_exception();
    started_ = true;
    changed_.notify_all();
    return;
  }
  {
    const std::lock_guard lock(mutex_);
    player_ = holder.get();
    started_ = open_ = true;
    changed_.notify_all();
  }
  // Without vsync (a virtual screen) a frame returns at once: at most 60 a second, so the loop
  // leaves the CPU to the script.
  constexpr auto kFramePeriod = std::chrono::microseconds(16667);
  auto next = std::chrono::steady_clock::now();
  for (;;) {
    bool want_screenshot;
    {
      const std::lock_guard lock(mutex_);
      if (stop_) break;
      want_screenshot = screenshot_wanted_;
    }
    bool running = true;
    if (want_screenshot) {
      Image8 frame;
      running = holder->player.run(1, &frame) == 1;
      const std::lock_guard lock(mutex_);
      screenshot_ = std::move(frame);
      screenshot_wanted_ = false;
    } else {
      running = holder->player.run_frame();
    }
    {
      const std::lock_guard lock(mutex_);
      ++frames_;
      on_display_ = holder->player.state().on_display;
      if (!running) open_ = false;
      changed_.notify_all();
      if (!running) break;
    }
    next += kFramePeriod;
    const auto now = std::chrono::steady_clock::now();
    if (next > now) std::this_thread::sleep_until(next);
    else next = now;
  }
  const std::lock_guard lock(mutex_);
  player_ = nullptr;
  open_ = false;
  holder.reset();  // GLFW and GL go on the thread that made them
  changed_.notify_all();
}

void ScriptWindow::run_renders() {
  for (;;) {
    RenderCall call;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [this] { return stop_ || pending_; });
      if (stop_) return;
      call = std::move(*pending_);
      pending_.reset();
      rendering_ = true;
    }
    try {
      PyQuilt quilt = render_quilt(call);
      show(std::move(quilt));
    } catch (...) {
      const std::lock_guard lock(mutex_);
      error_ = std::current_exception();
    }
    const std::lock_guard lock(mutex_);
    rendering_ = false;
    changed_.notify_all();
  }
}

void ScriptWindow::throw_pending_error() {
  if (!error_) return;
  const std::exception_ptr e = error_;
  error_ = nullptr;
  std::rethrow_exception(e);
}

void ScriptWindow::show(PyQuilt quilt) {
  std::unique_lock lock(mutex_);
  if (!open_) throw_input_error("window: closed");
  play::QuiltPicture picture{std::move(quilt.image), quilt.layout, "lfd.Window"};
  player_->player.show_quilt(std::move(picture));  // thread-safe: queued for the next frame
  shown_after_ = frames_ + 2;
}

void ScriptWindow::render(RenderCall call) {
  const std::lock_guard lock(mutex_);
  throw_pending_error();
  if (!open_) throw_input_error("window: closed");
  pending_ = std::move(call);
  changed_.notify_all();
}

void ScriptWindow::wait() {
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [this] { return !open_ || (!pending_ && !rendering_ && frames_ >= shown_after_); });
  throw_pending_error();
}

Image8 ScriptWindow::screenshot() {
  std::unique_lock lock(mutex_);
  if (!open_) throw_input_error("window: closed");
  screenshot_.reset();
  screenshot_wanted_ = true;
  changed_.wait(lock, [this] { return !open_ || screenshot_.has_value(); });
  if (!screenshot_) throw_input_error("window: closed before the screenshot");
  Image8 frame = std::move(*screenshot_);
  screenshot_.reset();
  return frame;
}

bool ScriptWindow::on_display() const {
  const std::lock_guard lock(mutex_);
  return on_display_;
}

bool ScriptWindow::is_open() const {
  const std::lock_guard lock(mutex_);
  return open_;
}

void ScriptWindow::close() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
    changed_.notify_all();
  }
  if (render_thread_.joinable()) render_thread_.join();
  if (window_thread_.joinable()) window_thread_.join();
}

}  // namespace lfd::python
