#pragma once
// Synthetic display units for the calibration round trip (tests, `lfd bench calibration`,
// `lfd demo`): a TRUE unit (a real calibration plus a smooth correction warp and a view cone)
// and the NOMINAL description a user would start from (pitch off by 1 %, slant by 0.5 degree,
// any center), camera positions in front of it, and captures of the patterns made by the
// optics simulator (sim/simulator.hpp).
#include <cstdint>
#include <vector>

#include "display/calibration_file.hpp"
#include "sim/camera_effects.hpp"
#include "sim/camera_model.hpp"
#include "sim/capture_io.hpp"
#include "sim/patterns.hpp"
#include "sim/simulator.hpp"

namespace lfd::sim {

struct SyntheticUnitOptions {
  double warp_amplitude = 0.3;      // max |w| of the true correction field, lens periods
  double pitch_error_rel = 0.01;    // nominal pitch = true pitch * (1 + this)
  double slant_error_deg = 0.5;     // nominal slant = true slant + this
  double view_cone_error_deg = 2.0; // nominal cone = true cone - this
  uint64_t seed = 1;
};

struct SyntheticUnit {
  display::Calibration truth;    // display + gauge-free correction field
  display::Calibration nominal;  // what the patterns are made for (no correction)
};

SyntheticUnit make_synthetic_unit(const display::DisplayCalibration& real,
                                  const SyntheticUnitOptions& options = {});

struct CaptureRig {
  CameraIntrinsics intrinsics;
  std::vector<CameraPose> poses;
  CaptureEffects effects;
  bool glare_moves = false;  // new glare in every photo (a room that changes between photos)
};

// Where the rig's cameras stand. kSides: at clearly different distances and sides, a few hundredths
// of the distance above or below the centre. kAboveBelow: the positions of docs/calibration.md
// "With vertical parallax" (-0.06, +0.05, 0.45), (0.01, -0.04, 0.52), (0.07, +0.03, 0.60) m, scaled
// by the distance at which the screen spans 70 % of the image over 0.45 m (x1.05 for a 16" Gen2,
// x0.37 for a Portrait), so every display is framed alike and sees the same vertical parallax.
// kOffAxis: kSides' distances, the second camera 30 degrees to the right of the screen's centre and
// the third 25 degrees to the left, where the cover layer's refraction differs from a shift of the
// panel (docs/calibration.md, "The cover layer").
enum class RigLayout { kSides, kAboveBelow, kOffAxis };

// `positions` (1-3) cameras, with a `width_px` wide image in which the screen spans about 70 %
// of the width at the nearest distance; realistic effects (blur, 2 % noise, vignetting, lens
// distortion, 5 % glare) unless `clean`.
CaptureRig make_capture_rig(const display::DisplayCalibration& display, int width_px, int positions,
                            bool clean = false, uint64_t seed = 1,
                            RigLayout layout = RigLayout::kSides);

// Manual exposure for one camera, set on the white pattern as a user would: its brightest 1 %
// (the lens magnifies single subpixels into bright colour stripes) at 85 % of full scale.
// `effects.exposure` if nothing is lit.
// The effects of photo number `photo` at camera position `position` (0-based): its own noise,
// and the position's glare (reflections stay put while the camera does).
CaptureEffects photo_effects(const CaptureRig& rig, size_t position, size_t photo);

double exposure_on_white(const DisplaySimulator& simulator, const ImageF& white_panel,
                         const PhysicalCamera& camera, const CaptureEffects& effects);

// Simulates every pattern of `set` from every pose of `rig`.
std::vector<PositionCaptures> simulate_captures(const PatternSet& set, const display::Calibration& truth,
                                                const CaptureRig& rig);

// Errors of a calibration against the truth, in the units of the figures
// (docs/calibration.md section 4).
struct CalibrationErrors {
  double slant_deg = 0;        // |slant_est - slant_true|
  double pitch_rel = 0;        // |pitch_est / pitch_true - 1|
  double center_periods = 0;   // wrapped
  double view_cone_deg = 0;
  double correction_rms_periods = 0;  // rms over the screen of w_est - w_true
  double phase_rms_periods = 0;       // rms over the screen of A_est - A_true (all terms)
};
CalibrationErrors compare_with_truth(const display::Calibration& estimate, const display::Calibration& truth);

}  // namespace lfd::sim
