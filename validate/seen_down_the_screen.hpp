#pragma once
// What one viewer sees down the screen (vertical parallax; docs/display-model.md, "What a viewer
// sees: vertical parallax of slanted lenses"): a slanted lens has power only across its lines, so
// an eye at a fixed place sees different views at the top and the bottom of the screen even
// straight in front of it, by H_m line_tilt k / Cz of the cone (display/lens_relations.hpp).
// Measured through the simulator's optics and set beside the relation's prediction.
#include <vector>

#include <Eigen/Core>

#include "display/calibration_file.hpp"

namespace lfd::validate {

struct HeightSample {
  double y_m = 0;         // panel height of the samples (display frame, y up)
  double measured = 0;    // view fraction the eye sees there, through the optics, in [0, 1)
  double predicted = 0;   // seen_fraction() there, in [0, 1)
};

// `rows` heights from the bottom to the top of the central `region_fraction` of the screen,
// each averaged over a few lens periods around x = eye.x. Throws InputError for an eye behind
// the panel or fewer than 2 rows.
std::vector<HeightSample> seen_down_the_screen(const display::Calibration& truth,
                                               const Eigen::Vector3d& eye_m, int rows = 9,
                                               double region_fraction = 0.9);

// The wrapped difference a - b of two view fractions, in [-1/2, 1/2).
double fraction_difference(double a, double b);

}  // namespace lfd::validate
