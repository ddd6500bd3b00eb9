#pragma once
// Angular luminance profiles of isolated views (docs/validation.md "View separation"): for each
// view j a quilt with tile j white and the others black (and an all-black quilt for L_K) is
// interlaced with the ASSUMED calibration, then seen through the simulator following the TRUE
// calibration from directions theta sweeping the view cone, averaged over many points of the
// panel so the profile describes the whole screen, not one lens.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "display/calibration_file.hpp"
#include "interlace/interlacer.hpp"
#include "util/progress.hpp"

namespace lfd::validate {

struct ProfileOptions {
  int views = 0;                 // 0: the TRUE calibration's recommended view count
  double distance_m = 0.6;       // eye distance from each panel point
  // The eyes' height above the screen centre (display frame, metres). Unset: each eye is level
  // with its panel point, the angular profile in the horizontal plane. Set: every eye is at
  // this height, so across the screen's height the slanted lenses show it other views
  // (vertical parallax, lens_relations.hpp), as they do a real viewer.
  std::optional<double> eye_height_m;
  int angles_per_view = 8;       // theta samples across the cone, per view
  int panel_points = 1500;       // points averaged over (jittered grid)
  double region_fraction = 0.9;  // central part of the panel (width and height) sampled
  double psf_sigma_phase = -1;   // lens point spread; < 0: the TRUE calibration's, else default
  uint64_t seed = 1;             // jitter of the panel points
  interlace::ViewBlend blend = interlace::ViewBlend::kNearest;  // the interlacer's view selection

  // Throws InputError naming the option for impossible values.
  void check() const;
};

struct ViewProfiles {
  int views = 0;
  double distance_m = 0;
  std::optional<double> eye_height_m;
  double psf_sigma_phase = 0;
  int panel_points = 0;
  interlace::ViewBlend blend = interlace::ViewBlend::kNearest;
  std::vector<double> theta_deg;             // viewing directions, left to right
  std::vector<std::vector<double>> view;     // L_j(theta), [view][angle], luminance (white = 1)
  std::vector<double> black;                 // L_K(theta)
};

// The measurement. `assumed` drives the interlacer, `truth` the optics.
ViewProfiles measure_view_profiles(const display::Calibration& truth,
                                   const display::Calibration& assumed,
                                   const ProfileOptions& options, Progress* progress = nullptr);

}  // namespace lfd::validate
