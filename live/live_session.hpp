#pragma once
// A live calibration's photographs on disk, written as they are taken, in the layout
// `lfd calibrate DIR` reads (sim/capture_io.hpp), one capture folder per round:
//   DIR/live-session.json                  the plan (rounds, positions) and what is complete
//   DIR/round-R/patterns/                  round R's patterns and manifest (write_pattern_set)
//   DIR/round-R/camera.yaml                the intrinsics round R was solved with, if known
//   DIR/round-R/captures/posK/<stem>.png   16-bit RGB PNGs
// so a live run can be re-solved offline (`lfd calibrate DIR`: its last round) and resumed: a
// position is complete once every photo of it is on disk and the session file says so; a
// position begun but not completed is photographed again from the start.
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "sim/camera_model.hpp"
#include "sim/capture_io.hpp"
#include "sim/patterns.hpp"

namespace lfd::live {

struct LiveSessionPlan {
  int rounds = 2;
  int positions = 1;
};

class LiveSession {
 public:
  // Opens the session in `dir`, or starts one there if `dir` has no live-session.json (an
  // existing folder must then be empty). Throws InputError naming the file and field when
  // the session there was planned differently.
  LiveSession(std::filesystem::path dir, const LiveSessionPlan& plan);

  const std::filesystem::path& dir() const { return dir_; }
  std::filesystem::path round_dir(int round) const;
  static std::string position_name(int index) { return "pos" + std::to_string(index + 1); }

  // Round R's patterns as saved, if they are (a resumed round keeps the patterns it began
  // with); save_patterns writes them and returns them as `lfd calibrate` will read them.
  std::optional<sim::PatternSet> saved_patterns(int round) const;
  sim::PatternSet save_patterns(int round, const sim::PatternSet& set);
  // The intrinsics round R is solved with (none: self-calibrated), saved beside its captures.
  void save_camera(int round, const std::optional<sim::CameraIntrinsics>& camera);

  bool position_complete(int round, int index) const;
  // Removes what an interrupted run left of this position.
  void begin_position(int round, int index);
  // Saves one photograph (CV_32FC3 RGB in [0, 1]) as a 16-bit PNG and returns it as
  // read_capture will read it back, so the live solve and an offline one see the same data.
  cv::Mat save_photo(int round, int index, const std::string& stem, const cv::Mat& rgb,
                     std::string& path);
  void complete_position(int round, int index);
  // A completed position's photographs, read back.
  sim::PositionCaptures read_position(int round, int index, const sim::PatternSet& set) const;

 private:
  void write_state() const;

  std::filesystem::path dir_;
  LiveSessionPlan plan_;
  std::map<int, std::set<int>> complete_;  // round -> position indices
};

// The capture folder `lfd calibrate DIR` reads: DIR itself, or, for a live session folder,
// its last round (InputError when that round is not complete: resume it first).
std::filesystem::path capture_folder_of(const std::filesystem::path& dir);

}  // namespace lfd::live
