#pragma once
// `lfd bench play` (docs/play.md "Figures"): a synthetic 4K quilt video at 30 and 60 fps, encoded
// once with libavcodec's software H.264 encoder (media/synthetic_quilt.hpp) and kept in a work
// folder, then (1) decoded alone as fast as the decoder goes, (2) played by the Player in its
// window against vsync: frames decoded, shown and dropped per second, the time from the
// playlist command to the first frame on screen, the process's peak memory. Each measurement is
// repeated (--runs) after one warm-up run; medians with their spread.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "display/calibration_file.hpp"

namespace lfd::play {

struct PlayBenchOptions {
  display::Calibration calibration;
  std::string display_name;
  bool simulated_display = false;
  int width = 3840, height = 2160;  // the video
  int cols = 8, rows = 6;           // its tiling; the aspect is the tiles' own
  std::vector<int> frame_rates{30, 60};
  double seconds = 5;               // video length
  int runs = 3;                     // timed runs after one warm-up
  std::string codec = "libx264";
  std::filesystem::path work_dir = std::filesystem::temp_directory_path() / "lfd-bench-play";
  int decoder_threads = 0;          // 0: one per core
  bool hardware_decode = true;      // VA-API tried (the path taken is reported)
};

// The measurements of one frame rate, one sample per timed run (apps/bench_play.cpp summarises
// and prints them).
struct PlayBenchRow {
  std::string video;         // file name
  int fps = 0;
  int64_t frames = 0;        // in the video
  std::string decoder;       // the path taken: "software (h264, 2 threads; VA-API: ...)"
  std::vector<double> decode_only_per_s, play_decoded_per_s, play_shown_per_s, play_dropped, first_frame_s;
  size_t peak_rss_bytes = 0;  // over the playback runs
};

// Runs the benchmark; `log` gets a line per encoded video.
std::vector<PlayBenchRow> run_play_benchmark(const PlayBenchOptions& options, std::ostream& log);

}  // namespace lfd::play
