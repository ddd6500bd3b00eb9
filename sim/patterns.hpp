#pragma once
// Calibration patterns (docs/calibration.md section 1): what `lfd patterns` writes and `lfd
// calibrate` expects. Every pattern is a panel-resolution image for the NOMINAL display:
//   board   a ChArUco board (the same 2D image in every view) for registration and pose;
//   white / black   exposure normalisation and exposure checks;
//   phase k K phase-shifted sinusoids in the nominal view fraction,
//           subpixel s shows 0.5 + 0.5 cos(2 pi (f_nom(s) - k/K));
//   fringe x/y k   4 phase-shifted sinusoids along the panel's x (y) axis, the same in every
//           view (pixel x shows 0.5 + 0.5 cos(2 pi (x / period - k/4))): dense registration,
//           thousands of correspondences over the whole screen where the board gives ~40;
//   probe j k   for a panel nobody described (`undescribed`, no phase patterns): the gratings
//           of sim/lens_probes.hpp, K steps each, from which the lens is measured before a
//           described set is drawn for it.
// Every pattern except the board carries four ArUco markers in the panel corners whose ids
// encode the pattern index, so a capture of the wrong pattern or from a camera that moved is
// recognised (the ids and the marker positions are checked against the manifest).
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core.hpp>

#include "display/calibration_file.hpp"
#include "sim/lens_probes.hpp"
#include "util/image.hpp"

namespace lfd::sim {

enum class PatternKind { kBoard, kWhite, kBlack, kPhase, kFringeX, kFringeY, kProbe };
const char* to_string(PatternKind kind);

struct PatternInfo {
  std::string file;  // file name under patterns/ and captures/<position>/ (stem is what counts)
  PatternKind kind = PatternKind::kPhase;
  int step = 0;      // phase step k (kPhase, kFringeX, kFringeY, kProbe)
  int probe = 0;     // which of PatternSet::probes (kProbe)
  int index = 0;     // position in the manifest; corner marker ids are 4 * marker_group(index)
                     // + corner
};

// The corner markers' dictionary has 250 ids, 62 groups of four: a set of more patterns (an
// undescribed panel's probes) reuses them, index modulo 62.
inline int marker_group(int index) { return index % 62; }

struct BoardLayout {
  int squares_x = 0, squares_y = 0;
  int square_px = 0, marker_px = 0;
  int origin_x_px = 0, origin_y_px = 0;  // top-left corner of the board on the panel
  // Chessboard corner positions on the panel (OpenCV pixel coordinates: pixel centres at
  // integers, row 0 at the top), by ChArUco corner id.
  std::vector<cv::Point2d> corners_px;
};

struct CornerMarkers {
  int side_px = 0;   // marker side including its black border
  int quiet_px = 0;  // white quiet zone around it
  // Marker centres on the panel (OpenCV pixel coordinates), corners TL, TR, BR, BL.
  std::vector<cv::Point2d> centres_px;
};

struct PatternSet {
  display::Calibration nominal;  // the display the patterns were made for (its lens model is f_nom)
  // A panel nobody described: `nominal` holds the screen (size, DPI) and no lens; the set has
  // probes instead of phase patterns (plan_undescribed_patterns).
  bool undescribed = false;
  std::vector<LensProbe> probes;
  int probe_steps = 0;
  int phase_steps = 8;
  int fringe_steps = 4;       // per fringe axis (0: no fringe patterns, board-only registration)
  double fringe_period_px = 0;
  BoardLayout board;
  CornerMarkers markers;
  std::vector<PatternInfo> patterns;

  const PatternInfo* find(const std::string& stem) const;
  std::vector<const PatternInfo*> of_kind(PatternKind kind) const;
  // True if panel point (u, v) lies under a corner marker (no phase there).
  bool under_marker(double u, double v, double margin_px) const;
};

struct PatternOptions {
  int phase_steps = 8;          // K >= 3; 8 rejects gamma harmonics up to the 6th
  int board_squares_short = 6;  // ChArUco squares along the short panel side
  bool fringes = true;          // dense registration patterns (8 more photos per position)
};

// The pattern list and layout for a display (no pixels yet).
PatternSet plan_patterns(const display::Calibration& nominal, const PatternOptions& options = {});
// The coarse set for a panel nobody described: board, white, black, fringes and the lens
// probes for a screen_w x screen_h panel at `dpi` (the nominal holds only the screen).
PatternSet plan_undescribed_patterns(int screen_w, int screen_h, double dpi,
                                     const PatternOptions& options = {},
                                     const ProbeOptions& probes = {});
// Renders one pattern at panel resolution (8-bit RGB, row 0 = top).
Image8 render_pattern(const PatternSet& set, const PatternInfo& pattern);

// The ArUco dictionaries used by the board and by the corner markers.
cv::Ptr<cv::aruco::Dictionary> board_dictionary();
cv::Ptr<cv::aruco::Dictionary> marker_dictionary();
cv::Ptr<cv::aruco::CharucoBoard> make_board(const BoardLayout& layout);

// DIR/patterns/manifest.json and the PNGs; refuses to overwrite an existing manifest unless
// `force`.
void write_pattern_set(const std::filesystem::path& dir, const PatternSet& set, bool force);
// Reads DIR/patterns/manifest.json; throws InputError naming the file and field.
PatternSet read_pattern_set(const std::filesystem::path& dir);

}  // namespace lfd::sim
