#pragma once
// A panel nobody described (docs/calibration.md, "A panel nobody described"): its coarse
// photos (the probes of sim/lens_probes.hpp) give the lens (lens_probes.hpp); a described
// pattern set is then drawn for that lens in DIR/fine, photographed, and solved by the same
// pipeline, gates and sigmas as a described unit (calibrate.hpp). This file holds what the
// two steps share: the description the probes give, the fine set, and the report of what was
// measured and what was assumed.
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "calib/lens_probes.hpp"
#include "display/calibration_file.hpp"
#include "sim/patterns.hpp"

namespace lfd::calib {

// What nobody told lfd about the panel and it cannot yet see: held at these values.
struct UndescribedAssumptions {
  double view_cone_deg = 40.0;  // the fine set's coarse start and solve measure it (>= 2 distances)
  bool inv_view = true;         // a converging lens shows its right subpixels to the left
  display::CoverLayer cover;    // thickness 0: none given (a bare sheet)
  bool cover_given = false;
};

// The description the probes give: the coarse set's screen with the measured pitch and slope,
// center 0 (the fine set's coarse start finds it), the subpixel order the probes read (the
// fine set's colour-order check confirms it) and the assumptions.
display::Calibration description_from_probes(const sim::PatternSet& coarse,
                                             const ProbeLensEstimate& lens,
                                             const UndescribedAssumptions& assumptions);

// What the coarse set says of the cover: given to `lfd patterns --screen ... --cover-thickness`,
// or none (a bare sheet). The fine set carries the coarse set's cover, so either says it.
UndescribedAssumptions assumptions_of(const sim::PatternSet& coarse);
UndescribedAssumptions assumptions_of(const display::Calibration& nominal);

// The fine set for the lens the probes found: a described set (phase patterns in its view
// fractions, board, white, black, fringes) with the coarse set's board.
sim::PatternSet plan_fine_patterns(const sim::PatternSet& coarse,
                                   const display::Calibration& description);

// The probes' round (`lfd calibrate DIR` on the probe photos, and round 1 of `--live`): the
// lens the probes show in `captures` (one position), the description it gives and the fine
// set drawn for it. Throws InputError as measure_lens_from_probes.
struct ProbeRound {
  ProbeLensEstimate lens;
  display::Calibration description;
  sim::PatternSet fine;
};
ProbeRound fine_set_from_probes(const sim::PatternSet& coarse,
                                const sim::PositionCaptures& captures);

// Where the fine set of an undescribed folder lives: DIR/fine (patterns/ and captures/).
std::filesystem::path fine_folder(const std::filesystem::path& dir);

// The report's "undescribed" section: the lens the probes gave (the fine set's nominal, whose
// serial is "undescribed"), and what was assumed.
nlohmann::ordered_json undescribed_report(const display::Calibration& from_probes,
                                          const UndescribedAssumptions& assumptions);
// Refuses (InputError, one line) coarse photos that cannot tell the slant's sign: a probe
// photographed in fewer than all of its steps at a position (one photo of a grating cannot
// tell which way its moire runs), or no probe photos at all. `dir` holds captures/<position>/.
void check_probe_photos(const std::filesystem::path& dir, const sim::PatternSet& coarse);

// True for the fine set of an undescribed panel (its nominal came from the probes).
bool from_probes(const sim::PatternSet& set);
bool from_probes(const display::Calibration& nominal);

}  // namespace lfd::calib
