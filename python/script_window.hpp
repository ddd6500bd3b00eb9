#pragma once
// lfd.Window's engine: a play::Player (the display's window: full screen on its monitor, or the
// simulated display in a window) on a thread of its own, so a script's loop hands it quilts and
// scenes and goes on (docs/python.md "The display window"). GLFW and GL live on that thread
// (play/player.hpp); scenes are rendered on a second thread, the newest one asked for winning,
// so neither a slow render nor a busy loop holds the other up.
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "display/calibration_file.hpp"
#include "interlace/interlacer.hpp"
#include "python/quilt_binding.hpp"
#include "python/render_call.hpp"
#include "util/image.hpp"

namespace lfd::python {

struct ScriptWindowOptions {
  display::Calibration calibration;
  std::string display_name;
  bool simulated = false;  // the simulated-display window even when the display's monitor is there
  interlace::InterlaceOptions interlace;
};

class ScriptWindow {
 public:
  // Opens the window on its thread; throws what the Player throws (InputError without a desktop
  // session or a GL 4.5 context).
  explicit ScriptWindow(ScriptWindowOptions options);
  ~ScriptWindow();
  ScriptWindow(const ScriptWindow&) = delete;
  ScriptWindow& operator=(const ScriptWindow&) = delete;

  // Shows the quilt from the next frame on; returns at once.
  void show(PyQuilt quilt);
  // Renders the call on the render thread (replacing one not yet started) and shows it; returns
  // at once. A render's error comes back from the next show, render or wait.
  void render(RenderCall call);
  // Until everything asked so far is on screen (two frames after the last quilt was handed over).
  void wait();
  // The window's next frame: the framebuffer when full screen on the display, else the panel.
  Image8 screenshot();
  bool on_display() const;
  bool is_open() const;
  void close();

 private:
  void run_window(ScriptWindowOptions options);
  void run_renders();
  void throw_pending_error();  // with mutex_ held

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  bool stop_ = false, started_ = false, open_ = false, on_display_ = false;
  std::exception_ptr error_;
  int64_t frames_ = 0;             // frames run
  int64_t shown_after_ = 0;        // the frame by which the last quilt is on screen
  std::optional<RenderCall> pending_;
  bool rendering_ = false;
  bool screenshot_wanted_ = false;
  std::optional<Image8> screenshot_;
  struct PlayerHolder;
  PlayerHolder* player_ = nullptr;  // owned by the window thread
  std::thread window_thread_, render_thread_;
};

}  // namespace lfd::python
