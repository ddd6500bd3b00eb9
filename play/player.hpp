#pragma once
// `lfd play`'s engine (docs/play.md): a Player bound to one display (its calibration, the lens
// model, and one window: full screen on the display's monitor, or the simulated-display window
// of `lfd view` when the monitor is absent) that shows quilts decoded in memory and plays
// playlists of quilt images and quilt videos, interlaced on the GPU by gpu::GlInterlacer. The
// playlist, the clock and the rules of looping, seeking and skipping are play::Transport's
// (play/transport.hpp, no GL); the Player is its output and drives it once per frame.
//
// Threads. GLFW and GL live on the thread that built the Player (the program's main thread):
// construct it there and call run() / run_frame() there only. Every other
// public member function is THREAD-SAFE: the transport and content commands (show_quilt,
// set_playlist, play, pause, next, seek, ...) only append to a command queue under a mutex; the
// GL thread drains that queue at the start of each frame, in the order the commands came, so a
// network thread (`lfd serve`) may call them at any time; state() returns a copy taken under the
// same mutex, updated once per frame. Event callbacks (subscribe) run on the GL thread, between
// frames: they must not block, and must not call run_frame(); calling the thread-safe commands
// from them is allowed (they take effect the next frame).
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "display/calibration_file.hpp"
#include "gpu/gl/gl_flavour.hpp"
#include "interlace/interlacer.hpp"
#include "play/transport.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::play {

// A quilt decoded in memory (a caller that received the bytes over the network and decoded
// them with media::decode_quilt_image, say): 8-bit RGB pixels, rows top-down, and its tiling.
struct QuiltPicture {
  Image8 pixels;              // 3 channels, row 0 = top (as on disk)
  render::QuiltLayout layout;  // width/height must equal pixels' size
  std::string name;           // for state and messages
};

// A snapshot of the player, taken once per frame on the GL thread.
struct PlayerState {
  int entry_index = -1;       // -1: nothing, or a quilt from show_quilt
  int entry_count = 0;
  std::string entry_name;
  bool is_video = false;
  double position_s = 0;      // within the current entry
  double duration_s = 0;      // of the current entry (0 unknown)
  double frame_rate = 0;      // of the current video (0 for images)
  bool playing = false;       // false while paused or after the playlist ended
  bool looping = true;
  int64_t frames_shown = 0;    // swaps of the window since the start
  int64_t frames_decoded = 0;  // video frames decoded since the start
  int64_t frames_dropped = 0;  // video frames decoded but never shown (late)
  int64_t video_frame_index = -1;  // the video frame on screen (decode order from the start or
                                   // the last seek's keyframe is not used: index = round(pts * fps))
  double video_frame_pts_s = 0;      // its presentation time
  std::string decode_path;    // the current video's decoder: "software (N threads)", "VA-API"
  bool on_display = false;    // full screen on the display's monitor (else a simulated window)
  std::string gl;             // the window's GL: "llvmpipe (LLVM 15.0.6, 256 bits) (OpenGL ES 3.2 Mesa 22.3.6, GLFW window)"
  bool gl_es = false;         // OpenGL ES (gpu/gl/gl_flavour.hpp)
  bool window_visible = true;  // false once hidden (set_window_visible; Bridge's show_window)
  double quilt_aspect = 0;     // the shown quilt's view aspect (0: nothing shown)
  std::optional<rgbd::RgbdOptions> rgbd;  // the RGB-D settings of the picture shown, if RGB-D
  bool quit = false;
};

struct PlayerOptions {
  display::Calibration calibration;
  std::string display_name;         // for messages
  std::string monitor_prefix = "LKG";
  bool simulated_display = false;   // the window even when the display's monitor is there
  interlace::InterlaceOptions interlace;
  bool loop = true;                 // the playlist starts again after its last entry
  double image_duration_s = 10;     // an image entry's default duration
  bool hardware_decode = true;      // try the hardware decoders first (VA-API, V4L2; software when absent or failing)
  int decoder_threads = 0;          // 0: FFmpeg's choice (one per core)
  bool print_notices = true;        // skipped entries etc. on stderr
  // Desktop OpenGL 4.5, OpenGL ES 3.1, or auto: desktop, else ES with a notice (docs/arm.md).
  gpu::GlRequest gl = gpu::GlRequest::kAuto;
};

class Player {
 public:
  // Opens GLFW and the display window on the calling thread (which must stay the GL thread).
  // Throws InputError without a desktop session or a usable GL context (options.gl), or for a
  // calibration that cannot be interlaced.
  explicit Player(PlayerOptions options);
  ~Player();
  Player(const Player&) = delete;
  Player& operator=(const Player&) = delete;

  // --- thread-safe: queued, applied at the start of the next frame -------------------------
  // Replaces what is shown by one quilt held in memory (stays until the next command). A show
  // or playlist still waiting for its frame is dropped: the newest wins (play/command_queue.hpp).
  void show_quilt(QuiltPicture quilt);
  // Replaces the playlist and starts its entry `start` (bad entries are skipped then); replaces
  // a waiting show or playlist as show_quilt does.
  void set_playlist(std::vector<PlaylistEntry> entries, int start = 0);
  void play();
  void pause();
  void toggle_pause();
  void next();
  void previous();
  void go_to(int entry_index);
  // Within the current entry (clamped to [0, duration]); a video seeks to the frame shown at
  // that time.
  void seek(double seconds);
  // Relative to the current position.
  void seek_by(double seconds);
  void set_loop(bool loop);
  // Changes one RGB-D setting (a bridge.js key: focus, depthiness, zoom, crop_pos_x, ...; what
  // Bridge's update_current_entry sends) of the entry shown, if it is RGB-D, and redraws its
  // views; the playlist keeps the change. Throws InputError now, on the caller's thread, for an
  // unknown key or a value out of range; an entry that is not RGB-D is left as it is, with a
  // notice event.
  void update_rgbd_option(const std::string& key, const std::string& value);
  // Shows or hides the notice/help overlay (what the H key does). Off by default: nothing
  // covers the panel unless asked.
  void set_overlay(bool visible);
  // Changes the view aspect of the quilt shown (Bridge's update_current_entry `aspect`) and
  // redraws it; the playlist keeps the change. InputError now for an aspect outside (0, 100];
  // an RGB-D entry (its views are the display's) is left as it is, with a notice on stderr.
  void set_quilt_aspect(double aspect);
  // Hides the window (frames go on, unseen: playback keeps its clock) or shows it again.
  void set_window_visible(bool visible);
  void quit();
  // The interlaced panel of the next frame (screenW x screenH RGB, rows top-down: what the
  // display shows, whether full screen or in the simulated window), read back after that
  // frame is drawn and handed to `done` on the GL thread (so `done` must not block). Nothing
  // is read back while no one asks: a read-back of an 8K panel is tens of MB.
  void read_panel(std::function<void(Image8)> done);

  // A copy of the state as of the last frame.
  PlayerState state() const;

  // Callbacks run on the GL thread (see the top of this file). Returns an id for unsubscribe.
  int subscribe(std::function<void(const PlaybackEvent&)> callback);
  void unsubscribe(int id);

  // --- GL thread only ----------------------------------------------------------------------
  // One frame: drains the command queue, handles keys, advances the clock, decodes/uploads
  // what is due, interlaces, swaps (waits for vsync). Returns false once the player quits.
  bool run_frame();
  // Frames until quit (the window closed, Esc/Q, quit()); `max_frames` > 0 stops after that
  // many (scripted runs, `lfd play --frames N --screenshot F`, tests). Returns the number of
  // frames run. With `last_frame`, the last frame is read back before its swap into it: the
  // window's framebuffer (screenW x screenH RGB, rows top-down) when full screen on the
  // display, else the interlaced panel texture (the simulated window is scaled).
  int64_t run(int64_t max_frames = 0, Image8* last_frame = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lfd::play
