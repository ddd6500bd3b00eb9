#pragma once
// The control window's "seen from" preview: what an eye (or a camera) at a chosen angle, distance
// and height sees on the display, from the optics model `lfd simulate` uses (display::LensOptics,
// docs/validation.md "The forward model"). Each preview pixel is a point of the panel; the eye sees
// there the light the lens covering it sends toward the eye. It is drawn undistorted, the panel's
// own rectangle, so the views it shows line up with the panel and the quilt preview.
#include "display/lens_model.hpp"
#include "util/image.hpp"

namespace lfd::viewer {

// Without a nominal viewing distance in the display model, the eye sits where validation puts it.
inline constexpr double kDefaultSeenFromDistanceM = 0.6;

// The eye in the display frame (metres, origin at the panel centre, x right, y up, z toward
// the viewer).
struct SeenFromEye {
  double angle_deg = 0;  // horizontal angle from the panel normal, positive to the right (+x)
  double distance_m = kDefaultSeenFromDistanceM;  // from the panel centre
  double height_m = 0;   // above the panel centre
};

struct SeenFromOptions {
  int height_px = 256;            // preview height; its width follows the panel's aspect
  // Panel points per preview pixel: pixel centres of its footprint, at most this many across
  // and this many rows down, evenly spread.
  int pixels_across = 2;
  int rows_down = 8;
  double psf_sigma_phase = 0.008;  // the lens point spread (the calibration's, as lfd simulate)
  // Throws InputError naming the field.
  void check() const;
};

// The preview needs the panel on the CPU, a read-back of the whole panel texture (tens of MB
// on an 8K panel): only while the preview is shown, only when the frame or the eye changed
// since the last one, and at most every kSeenFromMinIntervalS. `seconds_since_last` < 0: none yet.
inline constexpr double kSeenFromMinIntervalS = 0.25;
bool seen_from_refresh_due(bool visible, bool changed, double seconds_since_last);

// The preview, RGB in [0, 1] (linear radiance as the simulator's, clamped), row 0 at the top.
// `panel` is what the display shows (screenW x screenH, 1, 3 or 4 channels, row 0 at the top).
ImageF seen_from_preview(const display::LensModel& lens, const ImageF& panel, const SeenFromEye& eye,
                         const SeenFromOptions& options = {});

}  // namespace lfd::viewer
