// lfd bench play: decode and playback rates of a synthetic 4K quilt video (play/play_bench.hpp).
#include <cstdio>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/timing_stats.hpp"
#include "play/play_bench.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {
namespace {

nlohmann::ordered_json row_json(const play::PlayBenchOptions& o, const play::PlayBenchRow& r) {
  nlohmann::ordered_json row;
  row["video"] = r.video;
  row["width"] = o.width;
  row["height"] = o.height;
  row["fps"] = r.fps;
  row["frames"] = r.frames;
  row["decoder"] = r.decoder;
  row["decode_only_frames_per_s"] = bench::summarize(r.decode_only_per_s).to_json();
  row["play_decoded_frames_per_s"] = bench::summarize(r.play_decoded_per_s).to_json();
  row["play_shown_frames_per_s"] = bench::summarize(r.play_shown_per_s).to_json();
  row["play_dropped_frames"] = bench::summarize(r.play_dropped).to_json();
  row["time_to_first_frame_s"] = bench::summarize(r.first_frame_s).to_json();
  row["peak_rss_bytes"] = r.peak_rss_bytes;
  return row;
}

void print_table(const std::vector<play::PlayBenchRow>& rows) {
  std::cout << fmt::format("{:>4} {:>7} {:>13} {:>14} {:>9} {:>9} {:>12} {:>9}  {}\n", "fps", "frames",
                           "decode-only/s", "play decoded/s", "shown/s", "dropped", "first frame", "peak RSS",
                           "decoder");
  for (const auto& r : rows)
    std::cout << fmt::format("{:>4} {:>7} {:>13.1f} {:>14.1f} {:>9.1f} {:>9.0f} {:>9.0f} ms {:>6.2f} GB  {}\n", r.fps,
                             r.frames, bench::summarize(r.decode_only_per_s).median,
                             bench::summarize(r.play_decoded_per_s).median, bench::summarize(r.play_shown_per_s).median,
                             bench::summarize(r.play_dropped).median, bench::summarize(r.first_frame_s).median * 1e3,
                             r.peak_rss_bytes / 1e9, r.decoder);
}

}  // namespace

int RunBenchPlay(int argc, char** argv) {
  CLI::App app{"Quilt video playback: a synthetic quilt video (3840x2160, 8x6 tiles, H.264, encoded once\n"
               "with libavcodec's software encoder into --work-dir) at 30 and 60 fps, decoded alone and\n"
               "played by lfd play's Player in its window: frames decoded, shown and dropped per second,\n"
               "time to the first frame, peak memory (medians of --runs after one warm-up). Needs a desktop\n"
               "session or Xvfb.\n"
               "Examples:\n"
               "  xvfb-run -s '-screen 0 1536x2048x24' lfd bench play --calibration tests/data/calibrations/"
               "LKG-PORT-portrait.visual.json --json play.json\n"
               "  lfd bench play --device auto --fps 30 --seconds 10",
               "bench play"};
  play::PlayBenchOptions o;
  DisplaySource source;
  source.add(app, "--calibration", "the display the player opens its window for");
  std::string json_path, size = "3840x2160", work_dir = o.work_dir.string();
  app.add_option("--size", size, "the video's size WxH (even)")->capture_default_str();
  app.add_option("--cols", o.cols, "columns of the quilt")->check(CLI::Range(1, 64))->capture_default_str();
  app.add_option("--rows", o.rows, "rows of the quilt")->check(CLI::Range(1, 64))->capture_default_str();
  app.add_option("--fps", o.frame_rates, "frame rates to measure")->check(CLI::Range(1, 240))->capture_default_str();
  app.add_option("--seconds", o.seconds, "video length")->check(CLI::Range(0.5, 120.0))->capture_default_str();
  app.add_option("--runs", o.runs, "timed runs after one warm-up")->check(CLI::Range(1, 50))->capture_default_str();
  app.add_option("--codec", o.codec, "libavcodec encoder for the video (libx264, libx265, libvpx-vp9)")->capture_default_str();
  app.add_option("--threads", o.decoder_threads, "decoder threads (0: one per core)")->capture_default_str();
  bool software = false;
  app.add_flag("--software-decode", software, "do not try VA-API");
  app.add_flag("--simulated", o.simulated_display, "the simulated-display window even on the display");
  app.add_option("--work-dir", work_dir, "where the encoded videos are kept")->capture_default_str();
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  if (auto code = parse(app, argc, argv)) return *code;
  const auto wh = parse_numbers(size, 'x', 2, "--size");
  o.width = int(wh[0]);
  o.height = int(wh[1]);
  o.work_dir = work_dir;
  o.hardware_decode = !software;
  o.calibration = source.load();
  o.display_name = source.name();
  const auto rows = play::run_play_benchmark(o, std::cout);
  print_table(rows);
  if (!json_path.empty()) {
    nlohmann::ordered_json result;
    result["benchmark"] = "play";
    result["display"] = o.display_name;
    result["runs"] = o.runs;
    result["warmup"] = 1;
    result["codec"] = o.codec;
    result["decoder_threads"] = o.decoder_threads;
    result["rows"] = nlohmann::ordered_json::array();
    for (const auto& r : rows) result["rows"].push_back(row_json(o, r));
    write_text_atomic(json_path, result.dump(2) + "\n");
    std::printf("\nwrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
