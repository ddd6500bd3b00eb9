#pragma once
// What the service protocols need from a display (docs/serve.md): the displays with their
// calibration and default quilt, showing a quilt held in memory, playlists, transport, the
// current entry's parameters, the state and playback events. `lfd serve` implements it on
// `lfd play`'s Player (player_display_service.hpp); the unit tests on a test double. Every call
// may come from any protocol thread at once: an implementation is thread-safe.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "display/calibration_file.hpp"
#include "rgbd/rgbd_options.hpp"
#include "util/image.hpp"

namespace lfd::serve {

// A quilt's layout as the clients send it (holoplay-core: vx, vy, vtotal, aspect; bridge.js:
// cols, rows, view_count, aspect).
struct QuiltSettings {
  int cols = 0;
  int rows = 0;
  int views = 0;       // cols * rows when the client does not say
  double aspect = 0;   // a view's width / height
};

struct ServedDisplay {
  int index = 0;
  std::string hwid;              // "LKG-..." (bridge.js lists displays whose hwid has "LKG")
  std::string hardware_version;  // "portrait", "go", ... or the monitor's name
  display::Calibration calibration;
  std::string calibration_source;  // "lfd calibration.json" or "factory visual.json"
  std::filesystem::path calibration_path;
  QuiltSettings default_quilt;
  int quilt_width_px = 0, quilt_height_px = 0;
  int window_x = 0, window_y = 0;
};

struct PlaylistEntry {
  std::filesystem::path file;  // a checked local file (serve/request_file.hpp)
  // An RGB-D entry's settings (isRGBD: bridge.js's keys, ranges and defaults, docs/rgbd.md);
  // none for a quilt.
  std::optional<rgbd::RgbdOptions> rgbd;
  QuiltSettings quilt;
  double focus = 0;
  int duration_ms = 0;  // 0: the player's default
};

struct Playlist {
  std::string name;
  bool loop = true;
  std::vector<PlaylistEntry> entries;
};

enum class Transport { kPlay, kPause, kNext, kPrevious, kSeekToIndex };

struct PlaybackState {
  std::string showing;   // what the display shows, in words ("quilt from holoplay-core 5x9", ...)
  std::string playlist;  // the playing playlist's name, empty if none
  int index = -1;        // the current entry
  int entries = 0;
  bool playing = false;
  bool window_visible = true;  // false after show_window(false)
  double quilt_aspect = 0;     // the view aspect of the quilt shown (update_current_entry's aspect)
  std::optional<rgbd::RgbdOptions> rgbd;  // the RGB-D settings of the picture shown (update_current_entry)
  double position_s = 0;   // within the entry shown
  double duration_s = 0;   // of the entry shown (0: unknown or nothing)
  bool is_video = false;   // the entry shown is a video (seek() moves within it)
};

// Events the event WebSocket forwards (bridge.js names: "New Item Playing", "Transport Control
// Play", ...).
struct PlaybackEvent {
  std::string name;
  std::string playlist;
  int head_index = -1;
};

class DisplayService {
 public:
  virtual ~DisplayService() = default;
  virtual std::vector<ServedDisplay> displays() const = 0;
  // Shows a decoded quilt (RGB) with its layout on display `display` until something else.
  virtual void show_quilt(int display, const Image8& quilt, const QuiltSettings& settings,
                          const std::string& label) = 0;
  // Back to the idle picture (holoplay `wipe`).
  virtual void wipe(int display) = 0;
  virtual void play_playlist(int display, const Playlist& playlist, int head_index) = 0;
  virtual void stop_playlist(const std::string& name) = 0;
  virtual void transport(Transport command, int index) = 0;
  // Within the entry shown (clamped to [0, its duration]); a video shows the frame at that time.
  virtual void seek(double seconds) = 0;
  // focus, depthiness, zoom, crop_pos_x, crop_pos_y, aspect, ... of the showing entry.
  virtual void update_current_entry(const std::string& parameter, double value) = 0;
  virtual void show_window(bool show) = 0;
  virtual PlaybackState state() const = 0;
  // The panel picture display `display` shows now (screenW x screenH RGB, row 0 at the top),
  // read back from its next frame; none when it did not come within `wait`. For the console's
  // "Seen from" (serve/seen_from.hpp). InputError for a display not served.
  virtual std::optional<Image8> panel_picture(int display, std::chrono::milliseconds wait) = 0;
  // Called from the display's thread for each playback event; one listener.
  virtual void set_event_listener(std::function<void(const PlaybackEvent&)> listener) = 0;
};

}  // namespace lfd::serve
