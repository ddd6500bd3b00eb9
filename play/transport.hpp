#pragma once
// `lfd play`'s transport (docs/play.md "The transport"): the playlist, the playback clock and the
// rules that move through it, with no window and no GL, so they run in unit tests on a fake
// clock. The Player (play/player.hpp) drives it once per frame and shows what it chose: the
// transport tells its output what to open, close and seek (TransportOutput), and the output
// tells the transport when the first frame of an entry is on screen, when a video ran out and
// when one turned corrupt. mpv keeps the same split: player/playloop.c and player/loadfile.c
// decide, video/out/ shows.
//
// The rules it owns: an entry that fails to open is skipped with its event (kEntrySkipped), not
// a stop; the playlist starts again after its last entry when looping (a playlist of one looping
// video rewinds it instead of opening it again); an image runs its entry's duration (or
// TransportOptions::image_duration_s), a video to its end (or its entry's duration, when given);
// a seek is clamped to [0, the entry's duration]; the clock runs only while playing and only
// from the entry's first frame on screen. Not thread-safe: one thread (the Player's GL thread)
// calls it.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "interlace/quilt_file.hpp"
#include "rgbd/rgbd_options.hpp"

namespace lfd::play {

// One playlist entry: a quilt image or a quilt video on disk.
struct PlaylistEntry {
  std::filesystem::path path;
  // The tiling when the file's `_qsCxRaA` name lacks it or is wrong (any field given overrides
  // the name; without name or override the entry is skipped with a notice).
  interlace::QuiltOverrides quilt;
  // How long an image stays (seconds; default PlayerOptions::image_duration_s). For a video:
  // nullopt plays it to its end; a value cuts it there (or repeats it until then).
  std::optional<double> duration_s;
  // Set: the file is an RGB-D image or video (colour and depth side by side, bridge.js
  // conventions, rgbd/rgbd_options.hpp) turned into the display's views on the GPU
  // (rgbd::GlRgbdViews) every new frame; `quilt` is then ignored.
  std::optional<rgbd::RgbdOptions> rgbd;
};

enum class PlaybackEventKind {
  kEntryStarted,   // a playlist entry (or a shown quilt) is on screen: its first frame was shown
  kEntryEnded,     // an entry ran its duration / its video ended
  kEntrySkipped,   // a bad entry (message says why), skipped
  kPaused,
  kResumed,
  kSeeked,
  kLoopRestarted,  // the playlist (or a looping video) started again
  kPlaylistEnded,  // the last entry ended and looping is off: the player shows black
  kQuit,           // the window closed, Esc/Q, or quit() was called
};

struct PlaybackEvent {
  PlaybackEventKind kind = PlaybackEventKind::kEntryStarted;
  int entry_index = -1;     // into the playlist; -1 for a quilt shown with show_quilt
  std::string entry_name;   // the file name (or QuiltPicture::name)
  double position_s = 0;    // within the entry
  std::string message;      // kEntrySkipped: the one-line reason
};

// What the output learnt of an entry it opened.
struct OpenedEntry {
  bool video = false;
  double video_length_s = 0;  // a video's own length (0: unknown)
};

// The side that shows the entries (the Player: decoding, upload, interlacing, the window).
class TransportOutput {
 public:
  virtual ~TransportOutput() = default;
  // Opens `entry` to be shown (a picture decoded, a video started). Throws InputError, naming
  // the file, for one that cannot be played.
  virtual OpenedEntry open(const PlaylistEntry& entry) = 0;
  // Lets go of what is shown: black until the next entry's first frame.
  virtual void close() = 0;
  // The video shown seeks: the next frame shown is the one at `seconds`.
  virtual void seek(double seconds) = 0;
};

struct TransportOptions {
  bool loop = true;               // the playlist starts again after its last entry
  double image_duration_s = 10;   // an image entry's default duration
  bool print_notices = true;      // a skipped entry's notice on stderr
};

// The playback clock: monotonic seconds from any origin (tests pass a fake one).
using TransportClock = std::function<double()>;
// std::chrono::steady_clock in seconds.
double steady_clock_seconds();

class Transport {
 public:
  // `output` must outlive the transport; `on_event` receives every event as it happens.
  Transport(TransportOptions options, TransportOutput& output,
            std::function<void(const PlaybackEvent&)> on_event, TransportClock clock = steady_clock_seconds);

  // --- commands ------------------------------------------------------------------------------
  // Replaces the playlist and starts its entry `start` (bad entries are skipped then). An
  // empty playlist only closes what was shown.
  void set_playlist(std::vector<PlaylistEntry> entries, int start = 0);
  // A picture the output already holds (a quilt from memory): the playlist is cleared and the
  // picture stays, playing, until the next command. Closes what was shown first.
  void show_picture(const std::string& name);
  void play() { set_playing(true); }
  void pause() { set_playing(false); }
  void toggle_pause() { set_playing(!playing_); }
  void next() { go_to(index_ + 1); }
  void previous() { go_to(index_ - 1); }
  // Entry `entry_index` modulo the playlist's length, playing.
  void go_to(int entry_index);
  // Within the current entry, clamped to [0, duration]; a video seeks to the frame at that time.
  void seek(double seconds);
  void seek_by(double seconds) { seek(position_ + seconds); }
  void set_loop(bool loop) { looping_ = loop; }
  void quit();

  // --- once per frame, from the output -------------------------------------------------------
  // Advances the clock by the time since the last tick, while playing an entry on screen.
  void tick();
  // A video's first frame after an open: the clock starts at its presentation time (ignored
  // once the entry is on screen).
  void first_frame_at(double pts_s);
  // The entry's first frame is on screen (kEntryStarted, once per entry).
  void picture_shown();
  // The current entry ends when its duration has run out, or when `media_ended` (its video
  // ran out): the next entry, the first again when looping, or the end of the playlist.
  void end_if_due(bool media_ended);
  // The entry cannot go on (a video turned corrupt midway): kEntrySkipped, then the next one.
  void skip_rest(const std::string& message);
  // kEntrySkipped for the current entry without moving on (a bad command: the old picture stays).
  void report_skipped(const std::string& message);

  // --- state ---------------------------------------------------------------------------------
  bool has_entry() const { return has_entry_; }
  int index() const { return index_; }  // -1: none, or a picture from show_picture
  int entry_count() const { return int(playlist_.size()); }
  // The playlist entry shown (the Player writes RGB-D changes back to it), or null.
  PlaylistEntry* current_entry();
  const std::string& entry_name() const { return name_; }
  bool is_video() const { return has_entry_ && opened_.video; }
  bool started() const { return started_; }
  double position_s() const { return position_; }
  // How long the entry runs: its duration, else a video's length; 0 unknown (or for ever).
  double duration_s() const;
  bool playing() const { return playing_; }
  bool looping() const { return looping_; }
  bool quitting() const { return quit_; }

 private:
  void set_playing(bool on);
  void close_entry();
  void start_entry(int first);
  void end_playlist();
  void advance();
  void emit(PlaybackEventKind kind, const std::string& message = {}, const std::string& name = {});

  TransportOptions options_;
  TransportOutput& output_;
  std::function<void(const PlaybackEvent&)> on_event_;
  TransportClock clock_;

  std::vector<PlaylistEntry> playlist_;
  int index_ = -1;
  bool has_entry_ = false;
  std::string name_;
  OpenedEntry opened_;
  double run_s_ = 0;           // the entry's duration (0: a video to its end; a picture for ever)
  bool started_ = false;       // its first frame is on screen (kEntryStarted sent)
  double position_ = 0;
  bool playing_ = true, looping_ = true, quit_ = false;
  std::optional<double> last_tick_s_;
};

// How long an entry runs (the rule of docs/play.md "Playlists"): an image its duration, else
// `image_duration_s`; a video its duration when given, else 0 (to its end).
double entry_run_time_s(const PlaylistEntry& entry, const OpenedEntry& opened, double image_duration_s);

}  // namespace lfd::play
