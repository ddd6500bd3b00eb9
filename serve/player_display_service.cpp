// The display service on lfd play's Players (docs/serve.md, "The display").
#include "serve/player_display_service.hpp"

#include <algorithm>
#include <fstream>
#include <future>
#include <set>
#include <thread>

#include <fmt/format.h>

#include "media/quilt_image.hpp"
#include "util/error.hpp"

namespace lfd::serve {

namespace {

// The RGB size of the largest picture among a playlist's image files, from their headers (the
// first 72 KiB of each: a PNG's or WebP's size is at its start, a JPEG's after its EXIF, which
// is at most 64 KiB);
// videos and files whose size is not found there count nothing.
std::size_t largest_picture_bytes(const Playlist& playlist) {
  std::size_t largest = 0;
  std::vector<std::uint8_t> head(72 * 1024);
  for (const PlaylistEntry& e : playlist.entries) {
    std::ifstream in(e.file, std::ios::binary);
    in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
    try {
      const media::ImageSize size = media::image_size({head.data(), static_cast<std::size_t>(in.gcount())}, e.file.string());
      largest = std::max(largest, std::size_t(size.width) * size.height * 3);
    } catch (const InputError&) {
    }
  }
  return largest;
}

// What a cast (a playlist of one still quilt picture) shows: its file and layout; empty for
// anything else (an RGB-D entry or a video moves or is made per frame; a longer playlist moves
// from entry to entry).
std::string still_playlist_key(const Playlist& playlist, int head_index) {
  if (playlist.entries.size() != 1) return {};
  std::string key = fmt::format("{} {}|", head_index, playlist.loop);
  for (const PlaylistEntry& e : playlist.entries) {
    if (e.rgbd || !media::is_image_file(e.file)) return {};
    key += fmt::format("{}:{}x{}:{}:{}:{}|", e.file.string(), e.quilt.cols, e.quilt.rows, e.quilt.views, e.quilt.aspect,
                       e.duration_ms);
  }
  return key;
}

// lfd_status reads the Player's state as of its last frame: a transport command waits (a second
// at most) for a whole frame after it was queued, so the event the API sends next and the state
// a page then reads agree (the console's live state, docs/console.md).
void wait_for_a_frame_after(const play::Player& p, std::int64_t frames_before) {
  for (int i = 0; i < 500 && p.state().frames_shown < frames_before + 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

}  // namespace

PlayerDisplayService::PlayerDisplayService(std::vector<play::Player*> players, std::vector<ServedDisplay> displays,
                                           MemoryBudget& budget)
    : players_(std::move(players)), displays_(std::move(displays)), budget_(budget), held_(players_.size()),
      handing_over_(std::make_unique<std::mutex[]>(players_.size())) {
  for (std::size_t i = 0; i < players_.size(); ++i)
    subscriptions_.push_back(players_[i]->subscribe(
        [this, i](const play::PlaybackEvent& e) { on_player_event(static_cast<int>(i), e); }));
}

PlayerDisplayService::~PlayerDisplayService() {
  for (std::size_t i = 0; i < players_.size(); ++i) players_[i]->unsubscribe(subscriptions_[i]);
}

play::Player& PlayerDisplayService::player(int display) const {
  if (display < 0 || display >= static_cast<int>(players_.size()))
    throw_input_error("display {}: not served (0..{})", display, players_.size() - 1);
  return *players_[display];
}

void PlayerDisplayService::show_quilt(int display, const Image8& quilt, const QuiltSettings& s, const std::string& label) {
  play::Player& p = player(display);
  // One copy for a display at a time: a show that comes while another is being handed over is
  // busy rather than a second copy in memory or a worker waiting (the newer would win anyway).
  std::unique_lock handing_over(handing_over_[display], std::try_to_lock);
  if (!handing_over.owns_lock()) throw BusyError("busy: another quilt is being handed to the display; try again");
  hold_for_display(display, quilt.pixels.size() * 10 / 3, "a quilt for the display");
  play::QuiltPicture picture;
  picture.pixels = quilt;
  picture.layout.cols = s.cols;
  picture.layout.rows = s.rows;
  picture.layout.views = s.views;
  picture.layout.aspect = s.aspect;
  picture.layout.width = quilt.width;
  picture.layout.height = quilt.height;
  picture.name = label;
  if (picture.layout.tile_width() < 1 || picture.layout.tile_height() < 1)
    throw_input_error("quilt: {} x {} pixels hold no {} x {} tiles", quilt.width, quilt.height, s.cols, s.rows);
  p.show_quilt(std::move(picture));
  std::lock_guard lock(mutex_);
  shown_key_[display].clear();
  showing_ = fmt::format("{} ({}x{} tiles, {} views)", label, s.cols, s.rows, s.views);
  if (display == playlist_display_) playlist_.clear();
}

// A display holds the picture shown (RGB), its quilt texture (RGBA: 4/3, which llvmpipe keeps in
// main memory) and the picture replacing it: a show's copy waiting for its frame, or a playlist
// picture being decoded (stb's buffer beside the picture it becomes). That is 10/3 of the
// newest content's RGB bytes; a replaced waiting show is dropped (play/command_queue.hpp), so it
// never adds up. Sized by the newest content, not added per request: a display never gets stuck
// on content it cannot replace.
void PlayerDisplayService::hold_for_display(int display, std::size_t bytes, const std::string& what) {
  std::lock_guard lock(hold_mutex_);
  MemoryBudget::Reservation& held = held_[display];
  if (bytes <= held.bytes()) {
    held.split(held.bytes() - bytes).release();
    return;
  }
  held.merge(budget_.reserve_or_busy(bytes - held.bytes(), what));
}

// The idle picture: a black quilt (one tile) in place of whatever was shown.
void PlayerDisplayService::wipe(int display) {
  play::QuiltPicture black;
  black.pixels = Image8(8, 8, 3);
  black.layout = {1, 1, 1, 1.0, 8, 8};
  black.name = "nothing (wiped)";
  play::Player& p = player(display);
  hold_for_display(display, black.pixels.pixels.size() * 10 / 3, "wipe");
  p.show_quilt(std::move(black));
  std::lock_guard lock(mutex_);
  shown_key_[display].clear();
  showing_ = "nothing (wiped)";
  if (display == playlist_display_) playlist_.clear();
}

void PlayerDisplayService::play_playlist(int display, const Playlist& playlist, int head_index) {
  std::vector<play::PlaylistEntry> entries;
  for (const PlaylistEntry& e : playlist.entries) {
    play::PlaylistEntry p;
    p.path = e.file;
    p.quilt.cols = e.quilt.cols;
    p.quilt.rows = e.quilt.rows;
    p.quilt.views = e.quilt.views;
    p.quilt.aspect = e.quilt.aspect;
    p.rgbd = e.rgbd;  // RGB-D: turned into views on the GPU by the player (docs/rgbd.md)
    if (e.duration_ms > 0) p.duration_s = e.duration_ms / 1000.0;
    entries.push_back(std::move(p));
  }
  if (entries.empty()) throw_input_error("playlist {}: no entries", playlist.name);
  play::Player& p = player(display);
  // The same still quilt cast again (bridge.js casts as a one-entry playlist, under another name
  // each time): the display already shows it, so nothing is decoded again on its thread
  // (decoding once per content, docs/serve.md "Memory"). Anything else plays anew.
  const std::string key = still_playlist_key(playlist, head_index);
  {
    std::lock_guard lock(mutex_);
    if (!key.empty() && key == shown_key_[display]) {
      playlist_ = playlist.name;
      playlist_display_ = display;
      showing_ = "playlist " + playlist.name;
      return p.play();
    }
  }
  hold_for_display(display, largest_picture_bytes(playlist) * 10 / 3, "playlist " + playlist.name);
  p.set_loop(playlist.loop);
  p.set_playlist(std::move(entries), std::max(head_index, 0));
  p.play();
  std::lock_guard lock(mutex_);
  shown_key_[display] = key;
  playlist_ = playlist.name;
  playlist_display_ = display;
  showing_ = "playlist " + playlist.name;
}

void PlayerDisplayService::stop_playlist(const std::string& name) {
  int display;
  {
    std::lock_guard lock(mutex_);
    if (playlist_ != name) return;
    display = playlist_display_;
  }
  wipe(display);
}

void PlayerDisplayService::transport(Transport command, int index) {
  int display;
  {
    std::lock_guard lock(mutex_);
    display = playlist_display_;
  }
  play::Player& p = player(display);
  const std::int64_t before = p.state().frames_shown;
  switch (command) {
    case Transport::kPlay: p.play(); break;
    case Transport::kPause: p.pause(); break;
    case Transport::kNext: p.next(); break;
    case Transport::kPrevious: p.previous(); break;
    case Transport::kSeekToIndex: p.go_to(index); break;
  }
  wait_for_a_frame_after(p, before);
}

void PlayerDisplayService::seek(double seconds) {
  int display;
  {
    std::lock_guard lock(mutex_);
    display = playlist_display_;
  }
  play::Player& p = player(display);
  const std::int64_t before = p.state().frames_shown;
  p.seek(seconds);
  wait_for_a_frame_after(p, before);
}

void PlayerDisplayService::update_current_entry(const std::string& parameter, double value) {
  // The RGB-D settings of the entry shown change its views on the next frame, the aspect a
  // quilt's tiles (docs/serve.md).
  static const std::set<std::string> rgbd_keys = {"focus", "depthiness", "zoom", "crop_pos_x", "crop_pos_y",
                                                  "depth_cutoff"};
  if (!rgbd_keys.count(parameter) && parameter != "aspect")
    throw_input_error("update_current_entry: {} is not adjustable by lfd play's player (docs/serve.md)", parameter);
  int display;
  {
    std::lock_guard lock(mutex_);
    display = playlist_display_;
  }
  if (parameter == "aspect") player(std::max(display, 0)).set_quilt_aspect(value);
  else player(std::max(display, 0)).update_rgbd_option(parameter, fmt::format("{}", value));
}

void PlayerDisplayService::show_window(bool show) {
  for (int d = 0; d < static_cast<int>(displays().size()); ++d) player(d).set_window_visible(show);
}

PlaybackState PlayerDisplayService::state() const {
  PlaybackState s;
  int display;
  {
    std::lock_guard lock(mutex_);
    s.showing = showing_.empty() ? "nothing yet" : showing_;
    s.playlist = playlist_;
    display = playlist_display_;
  }
  const play::PlayerState p = player(display).state();
  s.index = p.entry_index;
  s.entries = p.entry_count;
  s.playing = p.playing;
  s.window_visible = p.window_visible;
  s.quilt_aspect = p.quilt_aspect;
  s.rgbd = p.rgbd;
  s.position_s = p.position_s;
  s.duration_s = p.duration_s;
  s.is_video = p.is_video;
  if (!p.entry_name.empty() && !s.playlist.empty()) s.showing += ": " + p.entry_name;
  return s;
}

void PlayerDisplayService::set_event_listener(std::function<void(const PlaybackEvent&)> listener) {
  std::lock_guard lock(mutex_);
  listener_ = std::move(listener);
}

// The Player's events under Bridge's names (bridge.js's event list); the transport events come
// from the Bridge calls themselves (bridge_api.cpp), so the player's paused/resumed are not sent
// twice.
void PlayerDisplayService::on_player_event(int display, const play::PlaybackEvent& e) {
  std::string name;
  switch (e.kind) {
    case play::PlaybackEventKind::kEntryStarted: name = "New Item Playing"; break;
    case play::PlaybackEventKind::kPlaylistEnded: name = "Sync/Play Playlist Complete"; break;
    case play::PlaybackEventKind::kEntrySkipped: name = "lfd Entry Skipped"; break;
    default: return;
  }
  std::function<void(const PlaybackEvent&)> listener;
  PlaybackEvent out{name, "", e.entry_index};
  {
    std::lock_guard lock(mutex_);
    listener = listener_;
    if (display == playlist_display_) out.playlist = playlist_;
  }
  if (listener) listener(out);
}

std::optional<Image8> PlayerDisplayService::panel_picture(int display, std::chrono::milliseconds wait) {
  // Handed over from the GL thread; a promise the player drops unfulfilled (it quit) is a
  // broken promise here, and one that comes late goes to no one.
  auto promise = std::make_shared<std::promise<Image8>>();
  std::future<Image8> picture = promise->get_future();
  player(display).read_panel([promise](Image8 panel) { promise->set_value(std::move(panel)); });
  if (picture.wait_for(wait) != std::future_status::ready) return std::nullopt;
  try {
    return picture.get();
  } catch (const std::future_error&) {
    return std::nullopt;
  }
}

}  // namespace lfd::serve
