#pragma once
// The colour-order check (docs/calibration.md, 3.7): whether the photos agree with the subpixel
// layout the calibration will use (flipSubp: RGB or BGR stripes; Gen3 subpixel cells), from the
// phase each colour channel decodes on its own (channel_phase.hpp).
//
// A pattern gives each subpixel the nominal phase of the position the pattern set's layout
// puts it at. If channel c really sits elsewhere, it decodes psi + s pitch' (d_u + tilt d_v),
// d = described minus true position (screen units), s = -1 under invView: a constant offset
// per channel. Only the channels' differences can be seen (a common offset is the center), so
// each layout is compared by the R - G and B - G offsets it predicts with those measured
// (medians over every sample of every position). On the bench's 17-subpixel lenses RGB taken
// for BGR moves R - B by 2/3 pixel = 0.118 lens periods (docs/calibration.md).
//
// Candidates: the classic 1/3-pixel stride in either order and, when the pattern set's
// description has Gen3 cells, that cell table (the classic stride misplaces two of the three
// channels on such panels; docs/display-model.md "Vendor interlacing rules").
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "display/display_calibration.hpp"
#include "calib/decoding/phase_decoding.hpp"

namespace lfd::calib {

struct SubpixelLayout {
  bool cells = false;      // the description's Gen3 cell table (else the classic stride)
  bool flip_subp = false;  // classic stride: BGR (true) or RGB (false)
  bool operator==(const SubpixelLayout&) const = default;

  static SubpixelLayout of(const display::DisplayCalibration& d) {
    return {d.has_cells(), d.flip_subp && !d.has_cells()};
  }
  // "flipSubp 0 (RGB stripes)", "the description's subpixel cells (CellPatternMode 4)"
  std::string describe(const display::DisplayCalibration& description) const;
  // What to give `lfd calibrate` for this layout: "--flip-subp 0", or "no --flip-subp".
  std::string option() const;
  // `description` with this layout (the classic stride drops the cells).
  display::DisplayCalibration apply(const display::DisplayCalibration& description) const;
};

// The layouts worth comparing for a description: both classic orders, and its cells if any.
std::vector<SubpixelLayout> candidate_layouts(const display::DisplayCalibration& description);

// The per-channel phase offsets (R, G, B; lens periods) the photos show when the pattern was
// drawn for `pattern` but the panel has `layout`: phasor means over the pixels of every cell.
std::array<double, 3> predicted_channel_offsets(const display::DisplayCalibration& pattern,
                                                const SubpixelLayout& layout);

struct ColourOrderOptions {
  // Refuse only when the given layout misses by more than this many sigmas of the measured
  // differences ...
  double min_sigmas = 8.0;
  // ... and the best layout is nearer by this fraction of the distance between the two
  // (camera colour crosstalk dilutes the offsets; a third of the way is not "clearly").
  double min_margin_fraction = 0.35;
  bool estimate = false;  // adopt the best layout instead of refusing
};

struct ColourOrderCheck {
  long samples = 0;
  // Medians over all samples: R - G and B - G offsets, their standard errors and spreads.
  std::array<double, 2> measured_periods{0, 0};
  std::array<double, 2> sigma_periods{0, 0};   // standard error of the median
  std::array<double, 2> spread_periods{0, 0};  // robust per-sample sigma (1.4826 MAD)
  std::array<double, 3> channel_offsets_periods{0, 0, 0};  // medians against psi, R G B
  struct Candidate {
    SubpixelLayout layout;
    std::array<double, 2> predicted_periods{0, 0};  // R - G, B - G
    double miss_periods = 0;                        // |measured - predicted|
  };
  std::vector<Candidate> candidates;
  display::DisplayCalibration drawn;  // the description the patterns were drawn for
  SubpixelLayout pattern;    // its layout
  SubpixelLayout given;    // what the calibration would use (the pattern's, or --flip-subp)
  SubpixelLayout best;     // nearest to the photos
  bool photos_disagree = false;  // the photos clearly favour `best` over `given`
  SubpixelLayout adopted;        // given, or best when estimating
  std::string finding;           // one line: "flipSubp is 0, the photos say 1: ..."
  // The quality gate: the finding, when the photos disagree and nothing was adopted.
  bool refused() const { return photos_disagree && !(adopted == best); }
};

// Compares the layouts with the per-channel phases of every position. `given`: the layout the
// calibration is to use (the pattern set's unless the user named one).
ColourOrderCheck compare_subpixel_layouts(const display::DisplayCalibration& pattern,
                                          const SubpixelLayout& given,
                                          const std::vector<const DecodedPhase*>& positions,
                                          const ColourOrderOptions& options = {});

// The samples re-decoded for the adopted layout (each channel's predicted offset turned back
// before the channels are summed): nothing changes when it is the pattern's.
void correct_for_layout(const ColourOrderCheck& check, const display::DisplayCalibration& pattern,
                        const DecodedPhase& phase, std::vector<PhaseSample>& samples);

nlohmann::ordered_json to_json(const ColourOrderCheck& check);

}  // namespace lfd::calib
