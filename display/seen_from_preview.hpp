#pragma once
// "Seen from": what an eye (or a camera) at a chosen angle, distance and height sees on the
// display, from the optics model `lfd simulate` uses (display::LensOptics, docs/validation.md
// "The forward model"). Each preview pixel is a point of the panel; the eye sees there the light
// the lens covering it sends toward the eye. It is drawn undistorted, the panel's own rectangle,
// so the views it shows line up with the panel and the quilt. Used by the viewer's control
// window (docs/viewer.md) and by `lfd serve`'s console (docs/console.md).
#include "display/lens_model.hpp"
#include "util/image.hpp"

namespace lfd::display {

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

// The preview, RGB in [0, 1] (linear radiance as the simulator's, clamped), row 0 at the top.
// `panel` is what the display shows (screenW x screenH, 1, 3 or 4 channels, row 0 at the top).
ImageF seen_from_preview(const LensModel& lens, const ImageF& panel, const SeenFromEye& eye,
                         const SeenFromOptions& options = {});

// The horizontal angle (degrees) from which an eye level with the panel centre sees the middle
// of view `view` of `views` (view 0 at the cone's left edge; a fractional view lies between
// two): the direction of view fraction (view + 1/2) / views (lens_relations.hpp,
// tan_of_seen_fraction). Views 0 and views - 1 are the ends of the console's "Seen from"
// slider. Throws InputError for a view outside [-1/2, views - 1/2] (the cone) or not a number.
double seen_from_view_angle_deg(const LensModel& lens, double view, int views);

}  // namespace lfd::display
