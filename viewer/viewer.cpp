#include "viewer/viewer.hpp"

#include <algorithm>
#include <chrono>
#include <deque>
#include <iostream>
#include <memory>

#include <epoxy/gl.h>  // before GLFW, which would include GL/gl.h
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "gpu/gl/display_window.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/glfw_session.hpp"
#include "lightfield/scene_framing.hpp"
#include "render/default_camera.hpp"
#include "scene/gaussian_io.hpp"
#include "scene/scene_sequence.hpp"
#include "scene/scene_stream.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "util/progress.hpp"
#include "viewer/control_window.hpp"
#include "viewer/frame_pacing.hpp"
#include "viewer/input.hpp"
#include "viewer/light_field_frame.hpp"
#include "viewer/orbit_camera.hpp"
#include "viewer/seen_from_previewer.hpp"

namespace lfd::viewer {

using gpu::DisplayWindow;

namespace {

// Mouse and key state of both windows, filled by GLFW callbacks (user pointer).
struct InputCollector {
  InputEvents events;
  double last_x = 0, last_y = 0;
  bool have_last = false;
  bool left = false, right = false, shift = false;
  const ControlWindow* controls = nullptr;  // its ImGui may own the mouse
  GLFWwindow* control_window = nullptr;
  std::optional<std::string> dropped;
  bool toggle_controls = false;  // C pressed on the display window
  bool toggle_recording = false;  // V pressed on the display window

  bool ignore(GLFWwindow* w) const { return controls && w == control_window && controls->wants_mouse(); }
};

InputCollector* collector(GLFWwindow* w) { return static_cast<InputCollector*>(glfwGetWindowUserPointer(w)); }

void install_callbacks(GLFWwindow* w, InputCollector* in, bool chain_imgui) {
  glfwSetWindowUserPointer(w, in);
  // On the control window ImGui installed its callbacks first (chained); only add the camera's
  // through the polling below, so ImGui keeps working.
  if (chain_imgui) return;
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int mods) {
    InputCollector* c = collector(win);
    const bool down = action == GLFW_PRESS;
    c->shift = mods & GLFW_MOD_SHIFT;
    if (button == GLFW_MOUSE_BUTTON_LEFT) c->left = down;
    if (button == GLFW_MOUSE_BUTTON_RIGHT) c->right = down;
    c->have_last = false;
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
    InputCollector* c = collector(win);
    if (c->have_last && (c->left || c->right)) {
      const bool pan = c->right || c->shift;
      (pan ? c->events.pan_dx_px : c->events.drag_dx_px) += x - c->last_x;
      (pan ? c->events.pan_dy_px : c->events.drag_dy_px) += y - c->last_y;
    }
    c->last_x = x;
    c->last_y = y;
    c->have_last = true;
  });
  glfwSetScrollCallback(w, [](GLFWwindow* win, double, double dy) { collector(win)->events.wheel_steps += dy; });
  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int) {
    if (action == GLFW_PRESS && key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(win, GLFW_TRUE);
    if (action == GLFW_PRESS && key == GLFW_KEY_R) collector(win)->events.reset = true;
    if (action == GLFW_PRESS && key == GLFW_KEY_C) collector(win)->toggle_controls = true;
    if (action == GLFW_PRESS && key == GLFW_KEY_V) collector(win)->toggle_recording = true;
  });
  glfwSetDropCallback(w, [](GLFWwindow* win, int count, const char** paths) {
    if (count > 0) collector(win)->dropped = paths[0];
  });
}

// Keys held now (polled, so holding a key moves smoothly).
void poll_keys(GLFWwindow* w, InputEvents& e) {
  auto held = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS; };
  e.orbit_keys_x += held(GLFW_KEY_RIGHT) - held(GLFW_KEY_LEFT);
  e.orbit_keys_y += held(GLFW_KEY_UP) - held(GLFW_KEY_DOWN);
  e.pan_keys_x += held(GLFW_KEY_D) - held(GLFW_KEY_A);
  e.pan_keys_y += held(GLFW_KEY_W) - held(GLFW_KEY_S);
  e.zoom_keys += (held(GLFW_KEY_EQUAL) || held(GLFW_KEY_KP_ADD)) - (held(GLFW_KEY_MINUS) || held(GLFW_KEY_KP_SUBTRACT));
}

std::string timestamp() {
  const auto now = std::chrono::system_clock::now().time_since_epoch();
  return std::to_string(std::chrono::duration_cast<std::chrono::seconds>(now).count());
}

std::filesystem::path quilt_path_with_suffix(const std::filesystem::path& out, const render::QuiltLayout& q) {
  if (render::parse_quilt_name(out.filename().string())) return out;
  return out.parent_path() / (out.stem().string() + render::quilt_suffix(q.cols, q.rows, q.aspect) +
                              (out.has_extension() ? out.extension().string() : std::string(".png")));
}

void write_quilt(const LightFieldFrame& frame, const std::filesystem::path& out) {
  if (!frame.quilt().id()) {  // the direct method renders no quilt
    std::cout << "no quilt: the g2lf-direct method renders the panel straight from the planes\n";
    return;
  }
  const auto path = quilt_path_with_suffix(out, frame.layout());
  write_png(path, to_uint8(gpu::image_from_texture(frame.quilt())));
  std::cout << fmt::format("wrote {}\n", path.string());
}

void write_screenshot(const DisplayWindow& window, const LightFieldFrame& frame, const std::filesystem::path& out) {
  // On the display the window holds exactly the panel; a simulated window is scaled, so the
  // panel texture is the screenshot there.
  write_png(out, window.on_display() ? window.read_back_buffer() : to_uint8(gpu::image_from_texture(frame.panel())));
  std::cout << fmt::format("wrote {}\n", out.string());
}

// Terminal (lfd::Progress: a bar on a terminal, silent in logs) and, when it is open, the
// control window, between the pieces of an upload of more than one piece.
UploadProgress upload_progress(ControlWindow* controls, GLFWwindow* display) {
  struct Bar {
    std::unique_ptr<Progress> terminal;
    size_t done = 0;
  };
  auto bar = std::make_shared<Bar>();
  return [controls, display, bar](size_t done, size_t total) {
    if (total <= kUploadPieceGaussians) return;  // one piece: nothing to show between pieces
    if (!bar->terminal) {
      bar->terminal = std::make_unique<Progress>("uploading the scene", long(total));
      bar->done = 0;
    }
    bar->terminal->advance(long(done - bar->done));
    bar->done = done;
    if (controls) {
      glfwPollEvents();  // keep both windows responsive
      controls->draw_progress(fmt::format("uploading the scene: {} of {} Gaussians", done, total),
                              double(done) / double(total), display);
    }
    if (done == total) bar->terminal.reset();  // ends the terminal line
  };
}

void report_fit(const std::string& notice) {
  if (!notice.empty()) std::cerr << fmt::format("notice: {}\n", notice);
}

// The display's monitor, or none: a simulated display in a window (a desk without the unit).
GLFWmonitor* find_monitor(const gpu::GlfwSession& session, const ViewerOptions& options) {
  if (options.simulated_display) return nullptr;
  const auto& d = options.calibration.display;
  return session.display_monitor_or_none(options.monitor_prefix, d.screen_w, d.screen_h);
}

// The display's monitor is the only one (a small computer driving only the display): the control
// window would land on the panel, so it opens on request (C) and closing it hides it (docs/viewer.md).
bool controls_on_request(const gpu::GlfwSession& session, const DisplayWindow& display, const ViewerOptions& options) {
  const bool lone = options.controls && display.on_display() && session.monitors().size() <= 1;
  if (lone) std::cout << "the display is the only monitor: press C on it for the control window\n";
  return lone;
}

// Both windows feed one collector, so the camera moves from either; a scene dropped on the
// control window loads too.
void connect_input(InputCollector& input, const DisplayWindow& display, std::optional<ControlWindow>& controls) {
  install_callbacks(display.handle(), &input, false);
  if (!controls) return;
  input.controls = &*controls;
  input.control_window = controls->handle();
  glfwSetWindowUserPointer(controls->handle(), &input);
  glfwSetDropCallback(controls->handle(), [](GLFWwindow* win, int count, const char** paths) {
    if (count > 0) collector(win)->dropped = paths[0];
  });
}

// C opens or closes the control window (and closing it only hides it) when it opens on request.
void toggle_controls_on_request(const gpu::GlfwSession& session, InputCollector& input, const DisplayWindow& display,
                                std::optional<ControlWindow>& controls) {
  const bool close = controls && controls->should_close();
  if (!input.toggle_controls && !close) return;
  input.toggle_controls = false;
  if (controls) {
    input.controls = nullptr;
    input.control_window = nullptr;
    controls.reset();
  } else {
    controls.emplace(session, display.handle());
    connect_input(input, display, controls);
  }
  display.make_current();
}

// What the stages of the frame loop share: the windows, the frame, the camera and what one
// frame leaves to the next (docs/architecture.md, "Long pipelines are named stages").
struct FrameLoop {
  const ViewerOptions& options;
  const std::filesystem::path& settings_path;
  ViewerSettings& settings;
  scene::Scene& scene;
  OrbitCamera& camera;
  DisplayWindow& display;
  std::optional<ControlWindow>& controls;
  LightFieldFrame& frame;
  InputCollector& input;
  SeenFromPreviewer previewer;
  SeenFromControls seen_from{};
  std::string plane_notice{};
  FrameReport report{};
  FramePacing pacing{};
  std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
  std::unique_ptr<QuiltRecording> recording{};  // V pressed (or --record): the frames shown go here
  scene::SceneStream* stream = nullptr;          // a moving scene's frames, read ahead
  std::shared_ptr<const scene::Scene> shown{};   // the moving scene's frame on the GPU
  int shown_index = 0;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
};

// Seconds since the last frame; the control window shows the median and p99 of the recent
// ones (viewer/frame_pacing.hpp), which a single slow frame does not move.
double time_frame(FrameLoop& loop, int frame_index) {
  const auto now = std::chrono::steady_clock::now();
  const double dt = std::chrono::duration<double>(now - loop.last).count();
  loop.last = now;
  if (frame_index > 0) {
    loop.pacing.add(dt);
    const PacingFigures f = loop.pacing.figures();
    loop.report.frame_seconds = f.median_s;
    loop.report.frame_p99_seconds = f.p99_s;
  }
  return dt;
}

// Input: the mouse and keys of both windows move the camera (a step capped at 0.1 s, so a
// stalled frame does not fling it).
void apply_frame_input(FrameLoop& loop, double dt) {
  InputCollector& input = loop.input;
  poll_keys(loop.display.handle(), input.events);
  if (loop.controls && !loop.controls->wants_keyboard()) poll_keys(loop.controls->handle(), input.events);
  int fb_w = 0, fb_h = 0;
  glfwGetFramebufferSize(loop.display.handle(), &fb_w, &fb_h);
  apply_input(input.events, fb_h, std::min(dt, 0.1), loop.camera);
  input.events = InputEvents{};
}

// Reload: a scene dropped on a window replaces the shown one; a bad file keeps the old scene.
void reload_dropped_scene(FrameLoop& loop) {
  InputCollector& input = loop.input;
  if (!input.dropped) return;
  try {
    loop.scene = scene::load_scene(*input.dropped);
    loop.display.make_current();
    loop.frame.replace_scene(loop.scene);
    report_fit(loop.frame.scene_fit_notice());
    loop.camera = OrbitCamera(lightfield::scene_framing(loop.scene));
    loop.stream = nullptr;  // a dropped scene stops a moving one
    std::cout << fmt::format("loaded {} ({})\n", *input.dropped, fmt::format("{} {}", loop.scene.size(), loop.scene.primitives()));
  } catch (const InputError& e) {
    std::cerr << fmt::format("notice: {}\n", e.what());  // the old scene stays
  }
  input.dropped.reset();
}

// A moving scene: the frame its clock says (a scripted run: one scene frame per frame shown,
// waited for), uploaded when it is read; one not read yet keeps the last one on screen. The
// camera stays: the framing is the first frame's.
void advance_moving_scene(FrameLoop& loop, int frame_index) {
  if (!loop.stream) return;
  const bool scripted = loop.options.frames > 0;
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop.started).count();
  const int index =
      (scripted ? frame_index : int(elapsed_s * loop.options.scene_fps)) % loop.stream->count();
  if (index == loop.shown_index) return;
  std::shared_ptr<const scene::Scene> next = loop.stream->frame(index, scripted);
  if (!next) return;  // not read yet: a dropped scene frame
  loop.display.make_current();
  loop.frame.replace_scene(*next);
  loop.shown = std::move(next);
  loop.shown_index = index;
}

// Render: the light field for the camera, interlaced onto the display; settings the controls
// made invalid keep the last frame (the first frame has none, so it fails).
void render_frame(FrameLoop& loop, int frame_index) {
  const ViewerOptions& options = loop.options;
  LightFieldFrame& frame = loop.frame;
  DisplayWindow& display = loop.display;
  display.make_current();
  try {
    loop.settings.check("settings");
    frame.render(loop.camera.spec(), loop.settings, &loop.report);
  } catch (const InputError& e) {
    if (frame_index == 0) throw;
    std::cerr << fmt::format("notice: {}\n", e.what());  // e.g. planes too large: keep the last frame
  }
  if (frame.plane_fit_notice() != loop.plane_notice) {
    loop.plane_notice = frame.plane_fit_notice();
    report_fit(loop.plane_notice);
  }
  loop.report.fit_notices.clear();
  for (const std::string& notice : {frame.scene_fit_notice(), loop.plane_notice, frame.raster_notice()})
    if (!notice.empty()) loop.report.fit_notices.push_back(notice);
  if (loop.controls) loop.previewer.update(loop.seen_from, frame, loop.camera.spec(), loop.settings);
  display.draw(frame.panel());
  const bool last_frame = options.frames > 0 && frame_index + 1 == options.frames;
  if (last_frame && !options.screenshot_path.empty()) write_screenshot(display, frame, options.screenshot_path);
  display.swap();
}

// Actions: the control window edits the settings and asks for screenshots, quilts, cam.json
// and saved settings, done here between frames.
void run_control_actions(FrameLoop& loop) {
  if (!loop.controls) return;
  const LightFieldFrame& frame = loop.frame;
  ControlImages images;
  images.quilt = frame.quilt().id() ? &frame.quilt() : nullptr;  // none with g2lf-direct
  images.seen_from = loop.previewer.texture();
  images.seen_from_age_s = loop.previewer.age_seconds();
  images.seen_from_cost_s = loop.previewer.last_compute_seconds();
  const ControlActions a =
      loop.controls->draw(loop.settings, loop.seen_from, loop.report, images, loop.display.handle());
  if (a.reset_camera) loop.camera.reset();
  if (a.screenshot) write_screenshot(loop.display, frame, "lfd-view-" + timestamp() + ".png");
  if (a.save_quilt) write_quilt(frame, "lfd-view-" + timestamp() + ".png");
  if (a.save_camera) {
    write_text_atomic("cam.json", render::camera_json_text(loop.camera.spec()));
    std::cout << "wrote cam.json\n";
  }
  if (a.save_settings) {
    save_settings(loop.settings_path, loop.settings);
    std::cout << fmt::format("wrote {}\n", loop.settings_path.string());
  }
}

void stop_recording(FrameLoop& loop) {
  if (!loop.recording) return;
  std::cout << fmt::format("wrote {}\n", loop.recording->finish().string());
  loop.recording.reset();
}

// Recording: V (or --record from the first frame) starts a quilt video of the frames shown, V
// stops it; a quilt that changes size (other views) ends it, as a video keeps one size.
void record_shown_frame(FrameLoop& loop, int frame_index) {
  const ViewerOptions& options = loop.options;
  const bool toggle = loop.input.toggle_recording || (frame_index == 0 && !options.record_path.empty());
  loop.input.toggle_recording = false;
  if (toggle && loop.recording) {
    stop_recording(loop);
  } else if (toggle) {
    if (!options.start_recording) {
      std::cerr << "notice: this lfd has no video encoder (built without playback): nothing recorded\n";
    } else if (!loop.frame.quilt().id()) {
      std::cerr << "notice: the g2lf-direct method renders no quilt: nothing to record\n";
    } else {
      const std::filesystem::path path =
          options.record_path.empty() ? std::filesystem::path("lfd-view-" + timestamp() + ".mp4") : options.record_path;
      loop.recording = options.start_recording(loop.frame.layout(), path);
      std::cout << "recording the quilts shown (V stops)\n";
    }
  }
  if (!loop.recording) return;
  loop.display.make_current();
  const Image8 quilt = to_uint8(gpu::image_from_texture(loop.frame.quilt()));
  try {
    loop.recording->add(quilt);
  } catch (const std::invalid_argument&) {
    std::cerr << "notice: the quilt changed size: the recording ends here\n";
    stop_recording(loop);
  }
}

// What a scripted run asked for after its last frame: the quilt and the camera.
void write_final_outputs(const ViewerOptions& options, const LightFieldFrame& frame, const OrbitCamera& camera) {
  if (!options.quilt_path.empty()) write_quilt(frame, options.quilt_path);
  if (!options.camera_out_path.empty()) {
    write_text_atomic(options.camera_out_path, render::camera_json_text(camera.spec()));
    std::cout << fmt::format("wrote {}\n", options.camera_out_path.string());
  }
}

}  // namespace

int run_viewer(const ViewerOptions& options) {
  const auto& d = options.calibration.display;
  // A moving scene starts from its first frame, read ahead from then on; it frames the camera.
  std::optional<scene::SceneStream> stream;
  if (scene::is_scene_sequence(options.scene_path.string()))
    stream.emplace(scene::find_scene_sequence(options.scene_path.string()), options.frames_ahead);
  scene::Scene scene = stream ? *stream->frame(0, true) : scene::load_scene(options.scene_path);
  const std::filesystem::path settings_path =
      options.settings_path.value_or(settings_path_for_display(options.display_name));
  ViewerSettings settings = load_settings(settings_path, ViewerSettings{});
  if (options.method) settings.method = *options.method;
  const render::CameraSpec start =
      options.camera_path ? render::read_camera_json(*options.camera_path) : lightfield::scene_framing(scene);
  OrbitCamera camera(start);

  const gpu::GlfwSession session("lfd view needs a desktop session (X11 or Wayland) to open its windows");
  DisplayWindow display(session, find_monitor(session, options), d.screen_w, d.screen_h);
  if (!options.vsync) display.set_swap_interval(0);  // --no-vsync: frames as fast as they render
  const gpu::GlInfo info = gpu::query_gl_info("GLFW window");
  std::cout << fmt::format("display {} on {}; rendering with {}\n", options.display_name,
                           display.on_display() ? "its monitor" : "a simulated display window", info.summary());
  // Before the scene, so a long upload shows its progress there.
  std::optional<ControlWindow> controls;
  const bool on_request = controls_on_request(session, display, options);
  if (options.controls && !on_request) controls.emplace(session, display.handle());
  if (controls && !display.on_display()) controls->place_beside(display.handle());
  display.make_current();
  FrameOptions frame_options;
  frame_options.upload_progress = upload_progress(controls ? &*controls : nullptr, display.handle());
  frame_options.raster = options.raster;
  LightFieldFrame frame(scene, options.calibration, info, frame_options);
  report_fit(frame.scene_fit_notice());

  InputCollector input;
  connect_input(input, display, controls);
  FrameLoop loop{.options = options, .settings_path = settings_path, .settings = settings,
                 .scene = scene, .camera = camera, .display = display, .controls = controls,
                 .frame = frame, .input = input, .previewer = SeenFromPreviewer(frame.calibration())};
  if (stream) loop.stream = &*stream;
  loop.report.renderer = info.summary();
  loop.report.display = fmt::format("{} ({}x{})", options.display_name, d.screen_w, d.screen_h);
  for (int frame_index = 0; options.frames == 0 || frame_index < options.frames; ++frame_index) {
    glfwPollEvents();
    if (display.should_close() || (controls && controls->should_close() && !on_request)) break;
    if (on_request) toggle_controls_on_request(session, input, display, controls);
    const double dt = time_frame(loop, frame_index);
    apply_frame_input(loop, dt);
    reload_dropped_scene(loop);
    advance_moving_scene(loop, frame_index);
    render_frame(loop, frame_index);
    record_shown_frame(loop, frame_index);
    run_control_actions(loop);
  }
  stop_recording(loop);
  display.make_current();
  write_final_outputs(options, frame, camera);
  // A scripted run says how its frames were paced (the intervals after the first frame).
  if (options.frames > 0 && loop.pacing.figures().frames > 0) {
    const PacingFigures f = loop.pacing.figures();
    std::cout << fmt::format("frame pacing: median {:.2f} ms, p99 {:.2f} ms over {} frame intervals ({})\n",
                             f.median_s * 1e3, f.p99_s * 1e3, f.frames, options.vsync ? "vsync" : "no vsync");
  }
  return 0;
}

}  // namespace lfd::viewer
