#pragma once
// The named stages of `calibrate_display` (calibrate.cpp is the controller that runs them in
// order, the way COLMAP's controllers are written). Each stage checks what it needs and
// throws an InputError naming the photo and what to change; none writes files.
//   1. detect_boards          the ChArUco board in every position's board photo
//   2. choose_camera          the given intrinsics, or self-calibration from the boards
//   per position:
//   3. register_position      camera pose from the board corners (lens shift corrected)
//   4. check_exposure         white/black contrast and saturation on the screen
//   5. identify_patterns      corner markers: the right pattern in each photo, no motion
//   6. refine_with_fringes    dense registration from the fringe photos
//   7. decode_position_phase  the K-step phase, with its own checks
//   8. position_data          the samples and the camera prior for the solver
//   8b. add_cover_derivatives how they move with the cover's thickness (when it is free)
//   then:
//   9. check_colour_order     each channel's phase against the subpixel layouts (colour_order.hpp)
//  10. solve_display          coarse start + one Ceres problem (lens_solver.hpp)
//  11. assemble_calibration   the calibration.json content from the solution
//  12. QualityGates::evaluate (quality_gates.hpp), and the colour-order check's refusal
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "calib/calibrate.hpp"
#include "display/lens_model.hpp"
#include "calib/registration/registration.hpp"

namespace lfd::calib {

// The patterns of a set by role.
struct PatternRoles {
  const sim::PatternInfo* board = nullptr;
  std::vector<const sim::PatternInfo*> phase, white, black, fringe_x, fringe_y;
  explicit PatternRoles(const sim::PatternSet& set);
  static std::string stem(const sim::PatternInfo* p);
};

// The lens array shows a panel feature displaced by the lens content shift along the row
// (lens_relations.hpp) for a camera at `camera` (nominal model): registration moves the
// features back by it.
class LensShift {
 public:
  explicit LensShift(const display::Calibration& nominal);
  // The shift in lens periods, [-1/2, 1/2), at panel pixel `px`.
  double periods(cv::Point2d px, const Eigen::Vector3d& camera) const;
  // The correction to add to panel pixel `px` (panel pixels).
  cv::Point2d correction_px(cv::Point2d px, const Eigen::Vector3d& camera) const;

 private:
  const display::DisplayCalibration& display_;
  display::LensModel lens_;
};

// 1.
std::vector<BoardDetection> detect_boards(const sim::PatternSet& set, const PatternRoles& roles,
                                          const std::vector<sim::PositionCaptures>& positions,
                                          const CalibrateOptions& options);
// 2. Sets outcome.camera and outcome.camera_self_calibrated (warns on a poor self-calibration;
// refuses boards that leave the focal length undetermined: options.max_focal_sigma_rel).
void choose_camera(const CalibrateOptions& options, const std::vector<BoardDetection>& boards,
                   const sim::PatternSet& set, CalibrationOutcome& outcome);

// What the per-position stages share.
struct PositionContext {
  const sim::PatternSet& set;
  const PatternRoles& roles;
  const CalibrateOptions& options;
  const LensShift& shift;
  const sim::PositionCaptures& captures;
  const BoardDetection& board;
  const sim::CameraIntrinsics& camera;
  std::vector<std::string>& warnings;
};

// The pose after each stage and the board-corner shifts it was fitted with.
struct PositionState {
  std::optional<Registration> registration;
  std::vector<cv::Point2d> board_shift;
  cv::Mat screen_mask;  // the screen in the photo
  // What the registration used besides the board: the corner markers' outer corners in the
  // white photo (register_position: at the screen's corners, where a coarse sheet's board of
  // 4 squares spans only the middle), then the fringe points too (refine_with_fringes).
  ExtraPoints extra;
  PositionReport report;
};

// 3. The board's corners and the corner markers' (every pattern but the board has them).
void register_position(const PositionContext& ctx, PositionState& state);
// 4.
void check_exposure(const PositionContext& ctx, PositionState& state);
// 5.
void identify_patterns(const PositionContext& ctx, const PositionState& state);
// 6. No-op for pattern sets without fringes; warns and keeps the board pose if too few decode.
void refine_with_fringes(const PositionContext& ctx, PositionState& state);
// 6b. Without --camera: the self-calibrated camera refitted to every position's board corners
// and fringe points with the lens shift removed (the boards' raw corners carry it: up to half
// a lens, a ramp across the screen with a jump where the seen view wraps, which biased the
// focal length and principal point); sets outcome.camera and camera_focal_sigma_rel. The
// positions are then registered again through it. Refuses a focal length still undetermined.
void refine_self_calibration(const sim::PatternSet& set, const CalibrateOptions& options,
                             const std::vector<BoardDetection>& boards,
                             const std::vector<PositionState>& states, CalibrationOutcome& out);
// 7.
DecodedPhase decode_position_phase(const PositionContext& ctx, PositionState& state);
// 8. `known_camera_m`: a camera position known by other means (replaces the registration's).
PositionData position_data(const PositionContext& ctx, const PositionState& state,
                           const DecodedPhase& phase, bool camera_self_calibrated,
                           const std::optional<Eigen::Vector3d>& known_camera_m);

// 8b. How the registered camera and each sample's panel point move per metre of cover
// thickness (registered again through a cover `step_m` thicker): the solve frees the
// thickness with them (SolverOptions::cover_sigma_m, docs/calibration.md "The cover layer").
void add_cover_derivatives(const PositionContext& ctx, const PositionState& state, PositionData& data,
                           double step_m = 0.005);

// 9. Sets outcome.colour_order; re-decodes `data`'s samples for the adopted layout (the
// given one, or with options.colour_order.estimate the one the photos favour) and returns the
// pattern set with that layout, which the solve and the calibration carry.
sim::PatternSet check_colour_order(const sim::PatternSet& set, const CalibrateOptions& options,
                              const std::vector<DecodedPhase>& phases,
                              std::vector<PositionData>& data, CalibrationOutcome& outcome);
// 10. Sets outcome.coarse, outcome.solve and the positions' refined cameras and residuals.
void solve_display(const sim::PatternSet& set, const std::vector<PositionData>& data,
                   const SolverOptions& options, CalibrationOutcome& outcome);
// 11.
display::Calibration assemble_calibration(const sim::PatternSet& set,
                                 const std::vector<sim::PositionCaptures>& positions,
                                 const CalibrateOptions& options,
                                 const CalibrationOutcome& outcome);

}  // namespace lfd::calib
