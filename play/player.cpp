#include "play/player.hpp"

#include <algorithm>
#include <iostream>
#include <map>
#include <mutex>

#include <epoxy/gl.h>  // before GLFW, which would include GL/gl.h
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include "display/lens_model.hpp"
#include "gpu/gl/display_window.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/panel/gl_interlacer.hpp"
#include "gpu/gl/glfw_session.hpp"
#include "play/command_queue.hpp"
#include "play/entry_content.hpp"
#include "play/player_keys.hpp"
#include "play/quilt_texture.hpp"
#include "play/transport.hpp"
#include "display/display_quilt.hpp"
#include "rgbd/gl_rgbd_views.hpp"
#include "util/error.hpp"

namespace lfd::play {

namespace {

bool same_layout(const render::QuiltLayout& a, const render::QuiltLayout& b) {
  return a.cols == b.cols && a.rows == b.rows && a.views == b.views && a.aspect == b.aspect && a.width == b.width &&
         a.height == b.height;
}

// The display's monitor, or none: the simulated-display window (as `lfd view` chooses).
GLFWmonitor* find_monitor(const gpu::GlfwSession& session, const PlayerOptions& options) {
  if (options.simulated_display) return nullptr;
  const auto& d = options.calibration.display;
  return session.display_monitor_or_none(options.monitor_prefix, d.screen_w, d.screen_h);
}

}  // namespace

// Everything below runs on the GL thread except enqueue, publish's readers and the subscriber
// table (each under its own mutex). The playlist, the clock and their rules are the transport's
// (play/transport.hpp); the Impl is its output: it decodes, uploads, interlaces and shows.
struct Player::Impl final : TransportOutput {
  PlayerOptions options;
  display::LensModel lens;
  gpu::GlfwSession session{"lfd play needs a desktop session (X11 or Wayland) to open its window"};
  std::unique_ptr<gpu::DisplayWindow> window;
  std::unique_ptr<QuiltTexture> quilt;
  std::unique_ptr<gpu::GlInterlacer> interlacer;
  render::QuiltLayout interlacer_layout;
  std::unique_ptr<gpu::Texture> panel;
  std::unique_ptr<rgbd::GlRgbdViews> rgbd_views;  // an RGB-D entry's frame -> its views
  std::unique_ptr<gpu::Texture> rgbd_quilt;
  std::unique_ptr<PlayerKeys> keys;
  std::string gl_summary;

  CommandQueue<Impl> commands;
  mutable std::mutex state_mutex;
  PlayerState published;
  std::mutex subscriber_mutex;
  std::map<int, std::function<void(const PlaybackEvent&)>> subscribers;
  int next_subscriber = 1;

  // Playback (GL thread).
  Transport transport;
  std::optional<EntryContent> content;
  bool has_picture = false;     // the quilt texture holds the entry's picture
  bool panel_dirty = true;      // a new picture (or layout) since the panel was interlaced
  bool overlay = false;
  int64_t shown = 0, dropped = 0, decoded_closed = 0;
  int64_t video_index = -1;
  double video_pts = 0;
  std::vector<std::function<void(Image8)>> panel_readers;  // read_panel() callers waiting for a frame

  explicit Impl(PlayerOptions o)
      : options(std::move(o)),
        lens(options.calibration.display, options.calibration.correction),
        transport({options.loop, options.image_duration_s, options.print_notices}, *this,
                  [this](const PlaybackEvent& event) { send(event); }) {
    const auto& d = options.calibration.display;
    window = std::make_unique<gpu::DisplayWindow>(session, find_monitor(session, options), d.screen_w, d.screen_h,
                                                  1024, options.gl);
    if (!window->desktop_unavailable().empty() && options.print_notices)
      std::cerr << gpu::es_fallback_notice(window->desktop_unavailable()) << "\n";
    glfwSetWindowTitle(window->handle(), window->on_display() ? "lfd play" : "lfd play (simulated display)");
    window->make_current();
    gl_summary = gpu::query_gl_info("GLFW window").summary();
    quilt = std::make_unique<QuiltTexture>();
    panel = std::make_unique<gpu::Texture>(GL_RGBA8, d.screen_w, d.screen_h);
  }

  ~Impl() override {
    window->make_current();  // GL objects go while their context is current
    content.reset();
    interlacer.reset();
    rgbd_views.reset();
    rgbd_quilt.reset();
    panel.reset();
    quilt.reset();
  }

  void enqueue(std::function<void(Impl&)> command) { commands.push(std::move(command)); }

  void drain_commands() {
    for (auto& command : commands.take()) {
      try {
        command(*this);
      } catch (const InputError& e) {  // a bad quilt handed over: the notice, the old picture stays
        if (options.print_notices) std::cerr << fmt::format("notice: {}\n", e.what());
        transport.report_skipped(e.what());
      }
    }
  }

  void update_rgbd_option(const std::string& key, const std::string& value) {
    if (!content || !content->rgbd)
      throw_input_error("{}: not an RGB-D entry, so {} does not apply", content ? content->name : "nothing shown", key);
    rgbd::set_rgbd_option(*content->rgbd, key, value);
    if (PlaylistEntry* entry = transport.current_entry(); entry && entry->rgbd) rgbd::set_rgbd_option(*entry->rgbd, key, value);
    panel_dirty = true;  // the views are made again from the same frame
  }

  void set_quilt_aspect(double aspect) {
    if (!content || content->rgbd) {
      if (options.print_notices)
        std::cerr << fmt::format("notice: aspect: {} is not a quilt; left as it is\n",
                                 content ? content->name : "nothing shown");
      return;
    }
    content->layout.aspect = aspect;
    if (PlaylistEntry* entry = transport.current_entry()) entry->quilt.aspect = aspect;
    panel_dirty = true;
  }

  // The transport's events to the subscribers.
  void send(const PlaybackEvent& event) {
    std::vector<std::function<void(const PlaybackEvent&)>> callbacks;
    {
      std::lock_guard lock(subscriber_mutex);
      for (const auto& [id, callback] : subscribers) callbacks.push_back(callback);
    }
    for (const auto& callback : callbacks) callback(event);
  }

  // --- TransportOutput ---
  OpenedEntry open(const PlaylistEntry& entry) override {
    content = open_entry(entry, options.calibration, {options.hardware_decode, options.decoder_threads});
    if (!content->video) return {};
    const media::VideoInfo& info = content->video->info();
    if (options.print_notices)
      std::cerr << fmt::format("{}: {}x{} {} at {:.3g} fps, decoder {}\n", content->name, info.width, info.height,
                               info.codec, info.frame_rate, content->video->decode_path());
    return {true, info.duration_s};
  }

  void close() override {
    if (content && content->video) decoded_closed += content->video->frames_decoded();
    content.reset();
    has_picture = false;
    panel_dirty = true;
    video_index = -1;
    video_pts = 0;
  }

  void seek(double seconds) override {
    if (content && content->video) content->video->seek(seconds);
  }

  // What is due now goes to the quilt texture; an entry past its end advances.
  void update_picture() {
    if (!content) return;
    if (content->still) {
      // An image that ran its course gives way before this frame's picture is chosen, so the frame
      // shows the next entry's picture (or the same image again, looping), not black between them.
      transport.end_if_due(false);
      return upload_new_still();
    }
    VideoStream& video = *content->video;
    try {
      if (auto frame = video.frame_due(transport.position_s(), dropped)) {
        quilt->upload(*frame);
        has_picture = true;
        panel_dirty = true;
        video_index = frame->index;
        video_pts = frame->pts_s;
        transport.first_frame_at(frame->pts_s);  // the clock starts at the first frame shown
      }
    } catch (const InputError& e) {
      if (options.print_notices) std::cerr << fmt::format("notice: skipped the rest: {}\n", e.what());
      return transport.skip_rest(e.what());
    }
    transport.end_if_due(video.finished());
    upload_new_still();  // a video that ended gave way to an image: shown in this frame
  }

  void upload_new_still() {
    if (!content || !content->still || has_picture) return;
    quilt->upload(*content->still);
    has_picture = true;
    panel_dirty = true;
  }

  // The quilt the interlacer reads: the picture itself, or the views an RGB-D frame makes.
  const gpu::Texture& shown_quilt() {
    if (!content->rgbd) return quilt->quilt();
    const render::QuiltLayout& q = content->layout;
    if (!rgbd_views) rgbd_views = std::make_unique<rgbd::GlRgbdViews>();
    if (!rgbd_quilt || rgbd_quilt->width() != q.width || rgbd_quilt->height() != q.height)
      rgbd_quilt = std::make_unique<gpu::Texture>(GL_RGBA8, q.width, q.height);
    rgbd_views->render(quilt->quilt(), *content->rgbd, q, *rgbd_quilt,
                       display::effective_view_cone_deg(options.calibration));
    return *rgbd_quilt;
  }

  // Interlaces only when the picture changed: a still quilt costs one interlace, then swaps.
  void draw() {
    window->make_current();
    if (panel_dirty) {
      if (content && has_picture) {
        if (!interlacer || !same_layout(interlacer_layout, content->layout)) {
          interlacer = std::make_unique<gpu::GlInterlacer>(lens, content->layout, options.interlace);
          interlacer_layout = content->layout;
        }
        interlacer->interlace(shown_quilt(), *panel);
      } else {
        const float black[4] = {0, 0, 0, 1};
        gpu::clear_texture(*panel, black);
      }
      panel_dirty = false;
    }
    window->draw(*panel);
    if (overlay) draw_overlay();
  }

  // On request only (H): a progress bar along the bottom edge of the window.
  void draw_overlay() {
    int fb_w = 0, fb_h = 0;
    glfwGetFramebufferSize(window->handle(), &fb_w, &fb_h);
    const double end = content ? transport.duration_s() : 0;
    const double fraction = end > 0 ? std::clamp(transport.position_s() / end, 0.0, 1.0) : 0.0;
    const bool playing = transport.playing();
    const int bar_h = std::max(4, fb_h / 100);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, fb_w, bar_h);
    glClearColor(0.15f, 0.15f, 0.15f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(0, 0, int(fb_w * fraction), bar_h);
    glClearColor(playing ? 0.9f : 0.9f, playing ? 0.9f : 0.6f, playing ? 0.9f : 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  }

  Image8 read_back() const {
    if (window->on_display()) return window->read_back_buffer();
    return to_uint8(gpu::image_from_texture(*panel));
  }

  // The panel just drawn, once for all who asked since the last frame.
  void hand_out_panel() {
    if (panel_readers.empty()) return;
    const Image8 picture = to_uint8(gpu::image_from_texture(*panel));
    for (auto& done : panel_readers) done(picture);
    panel_readers.clear();
  }

  void publish() {
    PlayerState s;
    s.entry_index = transport.index();
    s.entry_count = transport.entry_count();
    s.entry_name = content ? content->name : std::string();
    s.is_video = content && content->video;
    s.position_s = transport.position_s();
    s.duration_s = content ? transport.duration_s() : 0;
    if (s.is_video) {
      s.frame_rate = content->video->info().frame_rate;
      s.decode_path = content->video->decode_path();
    }
    s.playing = transport.playing();
    s.looping = transport.looping();
    s.frames_shown = shown;
    s.frames_decoded = decoded_closed + (s.is_video ? content->video->frames_decoded() : 0);
    s.frames_dropped = dropped;
    s.video_frame_index = video_index;
    s.video_frame_pts_s = video_pts;
    s.on_display = window->on_display();
    s.gl = gl_summary;
    s.gl_es = window->es();
    s.quilt_aspect = content ? content->layout.aspect : 0.0;
    if (content) s.rgbd = content->rgbd;
    s.window_visible = window->visible();
    s.quit = transport.quitting();
    std::lock_guard lock(state_mutex);
    published = std::move(s);
  }

  bool frame(Image8* capture) {
    glfwPollEvents();
    if (window->should_close()) transport.quit();
    drain_commands();
    if (transport.quitting()) {
      publish();
      return false;
    }
    transport.tick();
    update_picture();
    draw();
    hand_out_panel();
    if (capture) *capture = read_back();
    window->swap();
    ++shown;
    if (content && has_picture) transport.picture_shown();
    publish();
    return true;
  }
};

Player::Player(PlayerOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  impl_->keys = install_player_keys(*this, impl_->window->handle());
  impl_->publish();
}

Player::~Player() = default;

void Player::show_quilt(QuiltPicture picture) {
  auto shared = std::make_shared<QuiltPicture>(std::move(picture));
  impl_->commands.push_content([shared](Impl& p) {
    shared->layout.check(shared->name);
    if (shared->layout.width != shared->pixels.width || shared->layout.height != shared->pixels.height ||
        shared->pixels.channels != 3)
      throw_input_error("{}: the layout says {}x{} but the picture is {}x{}x{}", shared->name, shared->layout.width,
                        shared->layout.height, shared->pixels.width, shared->pixels.height, shared->pixels.channels);
    p.transport.show_picture(shared->name);
    EntryContent content;
    content.name = shared->name;
    content.layout = shared->layout;
    content.still = std::move(shared->pixels);
    p.content = std::move(content);
    p.panel_dirty = true;
  });
}

void Player::set_playlist(std::vector<PlaylistEntry> entries, int start) {
  auto shared = std::make_shared<std::vector<PlaylistEntry>>(std::move(entries));
  impl_->commands.push_content([shared, start](Impl& p) { p.transport.set_playlist(std::move(*shared), start); });
}

void Player::play() { impl_->enqueue([](Impl& p) { p.transport.play(); }); }
void Player::pause() { impl_->enqueue([](Impl& p) { p.transport.pause(); }); }
void Player::toggle_pause() { impl_->enqueue([](Impl& p) { p.transport.toggle_pause(); }); }
void Player::next() { impl_->enqueue([](Impl& p) { p.transport.next(); }); }
void Player::previous() { impl_->enqueue([](Impl& p) { p.transport.previous(); }); }
void Player::go_to(int entry_index) { impl_->enqueue([entry_index](Impl& p) { p.transport.go_to(entry_index); }); }
void Player::seek(double seconds) { impl_->enqueue([seconds](Impl& p) { p.transport.seek(seconds); }); }
void Player::seek_by(double seconds) { impl_->enqueue([seconds](Impl& p) { p.transport.seek_by(seconds); }); }
void Player::update_rgbd_option(const std::string& key, const std::string& value) {
  if (key == "depth_loc" || key == "depth-loc")
    throw_input_error("{}: changes the layout of the views; give it with the entry", key);
  rgbd::RgbdOptions checked;
  rgbd::set_rgbd_option(checked, key, value);  // a bad key or value throws here, not in a frame
  impl_->enqueue([key, value](Impl& p) { p.update_rgbd_option(key, value); });
}

void Player::set_loop(bool loop) { impl_->enqueue([loop](Impl& p) { p.transport.set_loop(loop); }); }
void Player::set_overlay(bool visible) { impl_->enqueue([visible](Impl& p) { p.overlay = visible; }); }
void Player::set_quilt_aspect(double aspect) {
  if (!(aspect > 0 && aspect <= 100)) throw_input_error("aspect: {} is outside (0, 100]", aspect);
  impl_->enqueue([aspect](Impl& p) { p.set_quilt_aspect(aspect); });
}
void Player::set_window_visible(bool visible) {
  impl_->enqueue([visible](Impl& p) { p.window->set_visible(visible); });
}
void Player::quit() {
  impl_->enqueue([](Impl& p) { p.transport.quit(); });
}

void Player::read_panel(std::function<void(Image8)> done) {
  impl_->enqueue([done = std::move(done)](Impl& p) mutable { p.panel_readers.push_back(std::move(done)); });
}

PlayerState Player::state() const {
  std::lock_guard lock(impl_->state_mutex);
  return impl_->published;
}

int Player::subscribe(std::function<void(const PlaybackEvent&)> callback) {
  std::lock_guard lock(impl_->subscriber_mutex);
  const int id = impl_->next_subscriber++;
  impl_->subscribers[id] = std::move(callback);
  return id;
}

void Player::unsubscribe(int id) {
  std::lock_guard lock(impl_->subscriber_mutex);
  impl_->subscribers.erase(id);
}

bool Player::run_frame() { return impl_->frame(nullptr); }

int64_t Player::run(int64_t max_frames, Image8* last_frame) {
  int64_t frames = 0;
  while (max_frames <= 0 || frames < max_frames) {
    const bool last = max_frames > 0 && frames + 1 == max_frames;
    if (!impl_->frame(last ? last_frame : nullptr)) break;
    ++frames;
  }
  return frames;
}

}  // namespace lfd::play
