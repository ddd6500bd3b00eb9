// `lfd play`: quilt images and quilt videos on the display (play/player.hpp, docs/play.md).
//   lfd play scene_qs5x9a1.6.png clip_qs8x6a0.75.mp4 --device auto --duration 8
//   lfd play playlist.json --calibration visual.json --monitor LKG
//   lfd play clip_qs5x9a1.6.mp4 --calibration visual.json --pause-at 2 --frames 5 --screenshot panel.png
#include <chrono>
#include <iostream>

#include <fmt/format.h>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "apps/rgbd_cli.hpp"
#include "media/quilt_image.hpp"
#include "rgbd/rgbd_options.hpp"
#include "play/entry_content.hpp"
#include "play/player.hpp"
#include "play/player_keys.hpp"
#include "play/playlist.hpp"
#include "util/error.hpp"

namespace lfd::apps {
namespace {

// The entries: the files of the command line (a .json file is a playlist, expanded in place).
std::vector<play::PlaylistEntry> collect_entries(const std::vector<std::string>& files,
                                                 const interlace::QuiltOverrides& quilt,
                                                 const std::optional<rgbd::RgbdOptions>& rgbd,
                                                 std::optional<double> duration, std::optional<bool>& loop) {
  std::vector<play::PlaylistEntry> entries;
  for (const std::string& file : files) {
    if (play::is_playlist_file(file)) {
      play::Playlist list = play::read_playlist_json(file);
      if (list.loop) loop = list.loop;
      for (auto& e : list.entries) entries.push_back(std::move(e));
      continue;
    }
    play::PlaylistEntry e;
    e.path = file;
    e.quilt = quilt;
    e.rgbd = rgbd;
    e.duration_s = duration;
    entries.push_back(std::move(e));
  }
  return entries;
}

// `--info`: what ran and what it held (docs/arm.md): the GL, the decoder, the frame rates.
void print_play_info(const play::PlayerState& s, double seconds) {
  std::cout << fmt::format("gl: {}{}\n", s.gl, s.gl_es ? " [OpenGL ES path]" : "");
  const double shown_rate = seconds > 0 ? double(s.frames_shown) / seconds : 0.0;
  const double video_rate = seconds > 0 ? double(s.frames_decoded - s.frames_dropped) / seconds : 0.0;
  if (s.frames_decoded > 0)
    std::cout << fmt::format("decoder: {}; video {:.3g} fps, held {:.1f} fps ({} decoded, {} dropped)\n",
                             s.decode_path.empty() ? "none" : s.decode_path, s.frame_rate, video_rate,
                             s.frames_decoded, s.frames_dropped);
  else
    std::cout << "decoder: none (no video shown)\n";
  std::cout << fmt::format("frames: {} shown in {:.2f} s ({:.1f} per second)\n", s.frames_shown, seconds, shown_rate);
}

}  // namespace

int RunPlay(int argc, char** argv) {
  CLI::App app{"Play quilt images (PNG, JPEG, WebP) and quilt videos (MP4/MOV H.264/H.265, WebM VP9/AV1)\n"
               "on the display: full screen on its monitor (a simulated display in a window when it is not\n"
               "connected), interlaced on the GPU with the unit's calibration. The tiling comes from the\n"
               "_qsCxRaA in the file name (or --cols/--rows/--aspect). Several files, or a playlist .json,\n"
               "play in turn (--duration seconds each image), looping. RGB-D images and videos (colour and\n"
               "depth side by side, bridge.js conventions) play with --rgbd and its options.\n"
               "Keys: space pause, Left/Right seek 5 s (images: previous/next), Up/Down previous/next,\n"
               "L looping, H help and progress bar (nothing covers the panel otherwise), Esc/Q quit.\n"
               "Examples:\n"
               "  lfd play scene_qs5x9a1.6.png --device auto\n"
               "  lfd play a_qs8x6a0.75.png clip_qs8x6a0.75.mp4 --calibration visual.json --duration 8\n"
               "  lfd play playlist.json --calibration visual.json --monitor LKG\n"
               "  lfd play clip_qs5x9a1.6.mp4 --calibration visual.json --pause-at 2 --frames 5 --screenshot panel.png\n"
               "  lfd play photo_rgbd.jpg --rgbd --depthiness 2 --device auto   (colour left, depth right)",
               "play"};
  std::vector<std::string> files;
  app.add_option("files", files, "quilt images, quilt videos or playlist .json files")->required();
  DisplaySource source;
  source.add(app, "--calibration", "the display: visual.json or calibration.json");
  play::PlayerOptions options;
  app.add_option("--monitor", options.monitor_prefix, "the display's monitor name prefix")->capture_default_str();
  app.add_flag("--simulated", options.simulated_display, "a simulated display in a window even if the display is connected");
  std::optional<double> duration;
  app.add_option("--duration", duration, "seconds each image is shown (videos: cut there); default 10 for images")
      ->check(CLI::PositiveNumber);
  interlace::QuiltOverrides quilt;
  app.add_option("--cols", quilt.cols, "quilt columns (overrides the name)")->check(CLI::Range(1, 256));
  app.add_option("--rows", quilt.rows, "quilt rows (overrides the name)")->check(CLI::Range(1, 256));
  app.add_option("--views", quilt.views, "number of views (default cols*rows)")->check(CLI::Range(1, 256));
  app.add_option("--aspect", quilt.aspect, "aspect of one tile's content")->check(CLI::PositiveNumber);
  bool is_rgbd = false;
  app.add_flag("--rgbd", is_rgbd, "the files are RGB-D (colour and depth side by side; any RGB-D option implies it)");
  RgbdFlags rgbd_flags;
  rgbd_flags.add(app, "--rgbd-settings", "RGB-D: ");
  bool no_loop = false, software = false, overscan = false, invert = false;
  app.add_flag("--no-loop", no_loop, "stop after the last entry");
  std::string blend = "nearest";
  app.add_option("--blend", blend, "view selection: nearest or linear")->check(CLI::IsMember({"nearest", "linear"}));
  app.add_flag("--overscan", overscan, "fill the panel and crop instead of black bars");
  app.add_flag("--invert", invert, "read the views in reverse order");
  app.add_flag("--software-decode", software, "do not try the hardware decoders (VA-API, V4L2 M2M)");
  app.add_option("--threads", options.decoder_threads, "video decoder threads (0: one per core)")->check(CLI::NonNegativeNumber);
  std::optional<double> pause_at;
  app.add_option("--pause-at", pause_at, "start paused at this time of the first entry (seconds)")->check(CLI::NonNegativeNumber);
  int64_t frames = 0;
  app.add_option("--frames", frames, "show this many frames, then quit (0: until closed)")->check(CLI::NonNegativeNumber);
  std::string screenshot;
  app.add_option("--screenshot", screenshot, "with --frames: the last frame as shown (PNG)");
  std::string gl = "auto";
  add_gl_option(app, gl);
  bool info = false;
  app.add_flag("--info", info, "at the end: the GL, the video decoder that ran and the frame rate held");
  if (auto code = parse(app, argc, argv)) return *code;
  options.gl = gl_request(gl);

  options.calibration = source.load();
  options.display_name = source.name();
  options.interlace.blend = interlace::parse_view_blend(blend);
  options.interlace.overscan = overscan;
  options.interlace.invert_views = invert;
  options.hardware_decode = !software;
  std::optional<bool> loop;
  // RGB-D when asked (--rgbd) or implied by any RGB-D option; nullopt: the files are quilts.
  std::optional<rgbd::RgbdOptions> rgbd;
  if (is_rgbd || rgbd_flags.any()) rgbd = rgbd_flags.options();
  std::vector<play::PlaylistEntry> entries = collect_entries(files, quilt, rgbd, duration, loop);
  options.loop = loop.value_or(!no_loop) && !no_loop;
  // One file: a bad one is an error (exit 2), not a skipped entry.
  if (entries.size() == 1) play::open_entry(entries[0], options.calibration, {!software, 1});

  play::Player player(options);
  int started = 0;
  bool ended = false;
  player.subscribe([&](const play::PlaybackEvent& e) {
    if (e.kind == play::PlaybackEventKind::kEntryStarted) ++started;
    if (e.kind == play::PlaybackEventKind::kPlaylistEnded) {
      ended = true;
      player.quit();
    }
  });
  player.set_playlist(std::move(entries));
  if (pause_at) {
    player.pause();
    player.seek(*pause_at);
  }
  std::cout << fmt::format("playing on {} ({}); press H for the keys\n", options.display_name,
                           player.state().on_display ? "its monitor" : "a simulated display window");
  Image8 last;
  const auto started_at = std::chrono::steady_clock::now();
  const int64_t ran = player.run(frames, screenshot.empty() ? nullptr : &last);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_at).count();
  const play::PlayerState s = player.state();
  if (started == 0 && ended) throw_input_error("no playable entry among {} file(s)", files.size());
  if (!screenshot.empty() && ran == frames && frames > 0) {
    write_png(screenshot, last);
    std::cout << fmt::format("wrote {}\n", screenshot);
  }
  std::cout << fmt::format("shown {} frames; video frames decoded {}, dropped {}{}\n", s.frames_shown,
                           s.frames_decoded, s.frames_dropped,
                           s.video_frame_index >= 0 ? fmt::format("; on screen: {} frame {} ({:.3f} s)", s.entry_name,
                                                                  s.video_frame_index, s.video_frame_pts_s)
                                                    : std::string());
  if (info) print_play_info(s, seconds);
  return 0;
}

}  // namespace lfd::apps
