#include "play/play_bench.hpp"

#include <thread>

#include <fmt/format.h>

#include "util/process_memory.hpp"
#include "media/synthetic_quilt.hpp"
#include "media/video_decoder.hpp"
#include "play/player.hpp"
#include "util/stopwatch.hpp"

namespace lfd::play {
namespace {

render::QuiltLayout bench_layout(const PlayBenchOptions& o) {
  render::QuiltLayout q;
  q.cols = o.cols;
  q.rows = o.rows;
  q.views = o.cols * o.rows;
  q.width = o.width;
  q.height = o.height;
  q.aspect = double(q.tile_width()) / q.tile_height();
  return q;
}

// The synthetic video, encoded once per size/rate/codec/length and kept in the work folder.
std::filesystem::path ensure_video(const PlayBenchOptions& o, int fps, std::ostream& out) {
  const render::QuiltLayout q = bench_layout(o);
  const auto path = o.work_dir / fmt::format("synthetic-{}x{}-{}fps-{}s-{}{}.mp4", o.width, o.height, fps, o.seconds,
                                             o.codec, render::quilt_suffix(q.cols, q.rows, q.aspect));
  if (std::filesystem::exists(path)) return path;
  std::filesystem::create_directories(o.work_dir);
  const Stopwatch stopwatch;
  media::EncoderOptions e;
  e.codec = o.codec;
  e.frame_rate = fps;
  const auto partial = path.string() + ".partial.mp4";
  media::write_synthetic_quilt_video(partial, q, int(std::lround(o.seconds * fps)), e);
  std::filesystem::rename(partial, path);
  out << fmt::format("encoded {} in {:.1f} s (once; kept for the next run)\n", path.string(), stopwatch.seconds());
  return path;
}

struct DecodeRun {
  double frames_per_s = 0;
  int64_t frames = 0;
  std::string path;
};

DecodeRun decode_all(const std::filesystem::path& video, const PlayBenchOptions& o) {
  media::VideoDecoder decoder(video, {o.hardware_decode, o.decoder_threads});
  const Stopwatch stopwatch;
  DecodeRun run;
  while (decoder.next_frame()) ++run.frames;
  run.frames_per_s = run.frames / stopwatch.seconds();
  run.path = decoder.decode_path();
  return run;
}

struct PlayRun {
  double shown_per_s = 0, decoded_per_s = 0, dropped = 0, first_frame_s = 0, wall_s = 0;
  int64_t shown = 0, decoded = 0;
};

PlayerOptions player_options(const PlayBenchOptions& o) {
  PlayerOptions po;
  po.calibration = o.calibration;
  po.display_name = o.display_name;
  po.simulated_display = o.simulated_display;
  po.loop = false;
  po.hardware_decode = o.hardware_decode;
  po.decoder_threads = o.decoder_threads;
  po.print_notices = false;
  po.gl = gpu::gl_request_from_env();  // LFD_GL=es: the figures on OpenGL ES (docs/arm.md)
  return po;
}

// One playback of the video, start to end, in the player's window (one Player, and so one
// window and GL context, for every run: opening them is not what is measured).
PlayRun play_once(Player& player, const std::filesystem::path& video) {
  bool ended = false;
  std::optional<double> first;
  const Stopwatch stopwatch;
  const int id = player.subscribe([&](const PlaybackEvent& e) {
    if (e.kind == PlaybackEventKind::kEntryStarted && !first) first = stopwatch.seconds();
    if (e.kind == PlaybackEventKind::kPlaylistEnded || e.kind == PlaybackEventKind::kEntrySkipped) ended = true;
  });
  const PlayerState before = player.state();
  PlaylistEntry entry;
  entry.path = video;
  player.set_playlist({entry});
  while (!ended && player.run_frame()) {
  }
  player.unsubscribe(id);
  const double wall = stopwatch.seconds();
  const PlayerState s = player.state();
  PlayRun run;
  run.wall_s = wall;
  run.first_frame_s = first.value_or(0);
  run.shown = s.frames_shown - before.frames_shown;
  run.decoded = s.frames_decoded - before.frames_decoded;
  run.dropped = double(s.frames_dropped - before.frames_dropped);
  const double playing = std::max(1e-9, wall - run.first_frame_s);
  run.shown_per_s = run.shown / playing;
  run.decoded_per_s = run.decoded / playing;
  return run;
}

}  // namespace

std::vector<PlayBenchRow> run_play_benchmark(const PlayBenchOptions& o, std::ostream& log) {
  std::vector<PlayBenchRow> rows;
  Player player(player_options(o));
  player.run(2);  // the window is up and has swapped
  for (const int fps : o.frame_rates) {
    PlayBenchRow row;
    const auto video = ensure_video(o, fps, log);
    row.video = video.filename().string();
    row.fps = fps;
    decode_all(video, o);  // warm-up (file cache, decoder start-up)
    for (int r = 0; r < o.runs; ++r) {
      const DecodeRun d = decode_all(video, o);
      row.decode_only_per_s.push_back(d.frames_per_s);
      row.frames = d.frames;
      row.decoder = d.path;
    }
    reset_peak_rss();
    play_once(player, video);  // warm-up
    for (int r = 0; r < o.runs; ++r) {
      const PlayRun p = play_once(player, video);
      row.play_decoded_per_s.push_back(p.decoded_per_s);
      row.play_shown_per_s.push_back(p.shown_per_s);
      row.play_dropped.push_back(p.dropped);
      row.first_frame_s.push_back(p.first_frame_s);
    }
    row.peak_rss_bytes = peak_rss_bytes();
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace lfd::play
