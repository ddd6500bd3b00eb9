#include "calib/calibration_stages.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <numbers>
#include <set>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "calib/solver/coarse_start.hpp"
#include "display/cover_rays.hpp"
#include "display/lens_relations.hpp"
#include "display/view_count.hpp"
#include "calib/registration/fringe_registration.hpp"
#include "calib/camera/planar_camera_calibration.hpp"
#include "sim/corner_markers.hpp"
#include "util/error.hpp"

namespace lfd::calib {

namespace {

using ojson = nlohmann::ordered_json;

// Pixels of the screen in the photo (the projected panel quad, shrunk by 3 %).
cv::Mat screen_mask(const Registration& reg, cv::Size size) {
  std::vector<display::ScreenUV> uv = {{0.03, 0.03}, {0.97, 0.03}, {0.97, 0.97}, {0.03, 0.97}};
  std::vector<cv::Point> poly;
  for (const auto& p : reg.uv_to_image(uv)) poly.emplace_back(int(p.x), int(p.y));
  cv::Mat mask(size, CV_8U, cv::Scalar(0));
  cv::fillConvexPoly(mask, poly, cv::Scalar(255));
  return mask;
}

struct Exposure {
  double clipped_fraction = 0, mean = 0;
};

Exposure exposure(const cv::Mat& rgb, const cv::Mat& mask, double saturation_level) {
  const float saturated = float(saturation_level);
  Exposure e;
  long n = 0, clipped = 0;
  double sum = 0;
  for (int y = 0; y < rgb.rows; y += 2) {
    const auto* row = rgb.ptr<cv::Vec3f>(y);
    const auto* m = mask.ptr<uint8_t>(y);
    for (int x = 0; x < rgb.cols; x += 2) {
      if (!m[x]) continue;
      ++n;
      const float mx = std::max({row[x][0], row[x][1], row[x][2]});
      if (mx >= saturated) ++clipped;
      sum += (row[x][0] + row[x][1] + row[x][2]) / 3.0;
    }
  }
  if (n) e.clipped_fraction = double(clipped) / n, e.mean = sum / n;
  return e;
}

std::string iso_time_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

}  // namespace

PatternRoles::PatternRoles(const sim::PatternSet& set)
    : board(set.of_kind(sim::PatternKind::kBoard).at(0)),
      phase(set.of_kind(sim::PatternKind::kPhase)),
      white(set.of_kind(sim::PatternKind::kWhite)),
      black(set.of_kind(sim::PatternKind::kBlack)),
      fringe_x(set.of_kind(sim::PatternKind::kFringeX)),
      fringe_y(set.of_kind(sim::PatternKind::kFringeY)) {}

std::string PatternRoles::stem(const sim::PatternInfo* p) {
  return std::filesystem::path(p->file).stem().string();
}

LensShift::LensShift(const display::Calibration& nominal)
    : display_(nominal.display), lens_(nominal.display, nominal.correction) {}

double LensShift::periods(cv::Point2d px, const Eigen::Vector3d& camera) const {
  const Eigen::Vector3d p = uv_to_display_m(display_, panel_px_to_uv(display_, px));
  const double f_seen =
      display::seen_fraction_through_cover(camera.x() - p.x(), camera.y() - p.y(), camera.z() - p.z(),
                                  display_.cover, lens_.line_tilt(), display_.view_cone_deg);
  return display::lens_content_shift(f_seen, display_.inv_view);
}

cv::Point2d LensShift::correction_px(cv::Point2d px, const Eigen::Vector3d& camera) const {
  return {-periods(px, camera) / lens_.pitch_periods() * display_.screen_w, 0.0};
}

std::vector<BoardDetection> detect_boards(const sim::PatternSet& set, const PatternRoles& roles,
                                          const std::vector<sim::PositionCaptures>& positions,
                                          const CalibrateOptions& options) {
  const size_t min_corners = size_t(options.min_board_corners);
  std::vector<BoardDetection> boards;
  const std::string stem = PatternRoles::stem(roles.board);
  for (const auto& pc : positions) {
    BoardDetection b = detect_board(sim::to_gray8(pc.image(stem)), set);
    if (b.ids.size() < min_corners && b.touches_border)
      throw_input_error(
          "{}: the screen is partly outside the photo (the board is cut off at the image "
          "border, {} ChArUco corners left); step back or re-aim so the whole screen shows",
          pc.path(stem), b.ids.size());
    if (b.ids.size() < min_corners)
      throw_input_error(
          "{}: no registration board found ({} ChArUco corners); show {} full screen, focus on "
          "the screen and keep all of it in the photo",
          pc.path(stem), b.ids.size(), roles.board->file);
    boards.push_back(std::move(b));
  }
  return boards;
}

void choose_camera(const CalibrateOptions& options, const std::vector<BoardDetection>& boards,
                   const sim::PatternSet& set, CalibrationOutcome& out) {
  if (options.camera) {
    out.camera = *options.camera;
    const cv::Size s = boards[0].image_size;
    if (out.camera.width != s.width || out.camera.height != s.height)
      throw_input_error("camera intrinsics are for {}x{} images, the captures are {}x{}",
                        out.camera.width, out.camera.height, s.width, s.height);
    return;
  }
  double rms = 0, focal_sigma_rel = 0;
  out.camera = self_calibrate(boards, set, &rms, &focal_sigma_rel);
  out.camera_self_calibrated = true;
  out.camera_focal_sigma_rel = focal_sigma_rel;
  // Boards seen nearly head-on leave the focal length undetermined: the camera would come out
  // tens of percent off and the view cone and center with it, while the solver takes the
  // camera as known. Measured on the Portrait unit: positions ~20 degrees apart give a sigma of
  // 5 % (error 1 %), the capture rig's near head-on positions 14 % (error 78 %).
  if (focal_sigma_rel > options.max_focal_sigma_rel)
    throw_input_error(
        "the board photos do not determine the camera's focal length (uncertainty {:.0f} %, at "
        "most {:.0f} % usable): photograph the positions about 20 degrees to the sides of the "
        "screen's axis, or pass --camera camera.yaml from a camera calibration",
        100 * focal_sigma_rel, 100 * options.max_focal_sigma_rel);
  if (rms > options.warn_self_calibration_rms_px)
    out.warnings.push_back(fmt::format(
        "camera self-calibration reprojection error {:.2f} px; a --camera file from a proper "
        "camera calibration will give a more accurate center",
        rms));
}

namespace {

// The outer corners of the white photo's corner markers (sim/corner_markers.hpp), each found
// near where the board's pose puts it: correspondences at the screen's corners. The board
// alone spans the middle of the screen (a coarse sheet's board has 4 squares on the short
// side), and a planar pose from a small patch trades lateral position for rotation: on the
// 20 LPI sheet its camera came out 66 mm off at 1.6x distance, enough to pick wrong fringe
// orders (docs/calibration.md, section 3.1).
ExtraPoints corner_marker_points(const PositionContext& ctx, const Registration& board_pose) {
  const sim::PatternSet& set = ctx.set;
  const sim::PatternInfo* white = ctx.roles.white.at(0);
  const auto found =
      detect_corner_marker_corners(sim::to_gray8(ctx.captures.image(PatternRoles::stem(white))));
  const display::DisplayCalibration& nd = set.nominal.display;
  const cv::Size size = ctx.board.image_size;
  const double search = ctx.options.marker_search_fraction * std::hypot(size.width, size.height);
  ExtraPoints out;
  for (int corner = 0; corner < 4; ++corner) {
    const auto it = found.find(4 * sim::marker_group(white->index) + corner);
    if (it == found.end()) continue;
    const std::array<cv::Point2d, 4> panel = sim::marker_outer_corners_px(set.markers, corner);
    std::vector<display::ScreenUV> uv;
    for (const auto& p : panel) uv.push_back(panel_px_to_uv(nd, p));
    const std::vector<cv::Point2d> predicted = board_pose.uv_to_image(uv);
    for (size_t k = 0; k < 4; ++k)
      if (cv::norm(predicted[k] - it->second[k]) <= search) {
        out.image_px.emplace_back(it->second[k]);
        out.panel_px.push_back(panel[k]);
      }
  }
  return out;
}

// `points` with their lens shifts for a camera at `camera`.
ExtraPoints shifted(ExtraPoints points, const LensShift& shift, const Eigen::Vector3d& camera) {
  points.shift_px.clear();
  for (const auto& p : points.panel_px) points.shift_px.push_back(shift.correction_px(p, camera));
  return points;
}

}  // namespace

void register_position(const PositionContext& ctx, PositionState& state) {
  const std::string board_path = ctx.captures.path(PatternRoles::stem(ctx.roles.board));
  auto& reg = state.registration;
  try {
    reg.emplace(ctx.board, ctx.set, ctx.camera);
    const ExtraPoints markers = corner_marker_points(ctx, *reg);
    reg.emplace(ctx.board, ctx.set, ctx.camera, std::vector<cv::Point2d>{},
                shifted(markers, ctx.shift, reg->camera_position_m()));
    // The lens array shows each board corner (and marker corner) displaced by the lens content
    // shift along the row (lens_relations.hpp); move them back for the pose.
    const Eigen::Vector3d c0 = reg->camera_position_m();
    state.board_shift.clear();
    for (int id : ctx.board.ids)
      state.board_shift.push_back(ctx.shift.correction_px(ctx.set.board.corners_px.at(size_t(id)), c0));
    state.extra = shifted(markers, ctx.shift, c0);
    reg.emplace(ctx.board, ctx.set, ctx.camera, state.board_shift, state.extra);
  } catch (const InputError& e) {
    throw_input_error("{}: {}", board_path, e.what());
  }
  PositionReport& rep = state.report;
  rep.board_corners = reg->corner_count();
  rep.reprojection_rms_px = reg->reprojection_rms_px();
  rep.camera_m = reg->camera_position_m();
  if (rep.camera_m.z() <= 0)
    throw_input_error("{}: the camera is not in front of the screen", board_path);
  const cv::Size size = ctx.board.image_size;
  for (const auto& p : reg->uv_to_image({{0, 0}, {1, 0}, {1, 1}, {0, 1}}))
    if (p.x < 0 || p.y < 0 || p.x > size.width - 1 || p.y > size.height - 1)
      throw_input_error(
          "{}: the screen is partly outside the photo (a screen corner falls at pixel "
          "({:.0f}, {:.0f}) of a {}x{} image); step back or re-aim so the whole screen shows",
          board_path, p.x, p.y, size.width, size.height);
  if (rep.reprojection_rms_px > ctx.options.warn_board_rms_px)
    ctx.warnings.push_back(fmt::format("{}: board reprojection error {:.2f} px (focus?)",
                                       board_path, rep.reprojection_rms_px));
  state.screen_mask = screen_mask(*reg, size);
}

void check_exposure(const PositionContext& ctx, PositionState& state) {
  const sim::PositionCaptures& pc = ctx.captures;
  const std::string white_stem = PatternRoles::stem(ctx.roles.white.at(0));
  const std::string black_stem = PatternRoles::stem(ctx.roles.black.at(0));
  const double saturation = ctx.options.saturation_level;
  const Exposure white = exposure(pc.image(white_stem), state.screen_mask, saturation);
  const Exposure black = exposure(pc.image(black_stem), state.screen_mask, saturation);
  if (white.clipped_fraction > ctx.options.max_clipped_fraction)
    throw_input_error(
        "{}: over-exposed: {:.0f} % of the screen is saturated; lower the exposure time or ISO "
        "(manual exposure, set on the white pattern)",
        pc.path(white_stem), 100 * white.clipped_fraction);
  if (white.mean - black.mean < ctx.options.min_contrast)
    throw_input_error(
        "{}: under-exposed: white and black differ by {:.1f} % of full scale; raise the "
        "exposure (manual exposure, set on the white pattern)",
        pc.path(white_stem), 100 * (white.mean - black.mean));
  state.report.clipped_fraction = white.clipped_fraction;
}

void identify_patterns(const PositionContext& ctx, const PositionState& state) {
  // Pattern identity and camera motion from the corner markers. A marker farther than
  // options.marker_search_fraction of the image from where the registration puts it is a false
  // detection.
  const sim::PatternSet& set = ctx.set;
  const sim::PositionCaptures& pc = ctx.captures;
  const CalibrateOptions& options = ctx.options;
  const Registration& reg = *state.registration;
  const display::DisplayCalibration& nd = set.nominal.display;
  const std::string board_path = pc.path(PatternRoles::stem(ctx.roles.board));
  std::vector<cv::Point2d> predicted_markers;
  {
    std::vector<display::ScreenUV> uv;
    for (const auto& c : set.markers.centres_px) uv.push_back(panel_px_to_uv(nd, c));
    predicted_markers = reg.uv_to_image(uv);
  }
  const cv::Size size = ctx.board.image_size;
  const double diag = std::hypot(size.width, size.height);
  const double lens_px =
      double(size.width) / display::shader_terms(nd.geometry(), nd.pitch_lpi, nd.slope).pitch_periods;
  std::map<int, cv::Point2d> reference;
  std::string reference_path;
  int verified = 0;
  for (const auto& p : set.patterns) {
    if (p.kind == sim::PatternKind::kBoard) continue;
    const std::string stem = PatternRoles::stem(&p);
    const auto markers = detect_corner_marker_corners(sim::to_gray8(pc.image(stem)));
    std::map<int, cv::Point2d> own;
    std::set<int> others;
    for (const auto& [id, corners] : markers) {
      const cv::Point2d centre = (corners[0] + corners[1] + corners[2] + corners[3]) * 0.25;
      if (cv::norm(centre - predicted_markers[size_t(id % 4)]) > options.marker_search_fraction * diag)
        continue;
      if (id / 4 == sim::marker_group(p.index)) {
        own[id % 4] = centre;
      } else if (id / 4 < int(set.patterns.size())) {
        others.insert(id / 4);
      }
    }
    if (own.empty() && !others.empty())
      throw_input_error("{}: shows pattern {}, expected {}", pc.path(stem),
                        set.patterns[size_t(*others.begin())].file, p.file);
    if (own.empty()) continue;
    ++verified;
    if (reference.empty()) {
      reference = own;
      reference_path = pc.path(stem);
      // The board capture has no corner markers: check it against this one through the
      // registration (tolerance: a lens of apparent shift plus the pose error).
      for (const auto& [corner, centre] : own) {
        const double moved = cv::norm(predicted_markers[size_t(corner)] - centre);
        if (moved > options.max_board_motion_px + lens_px + options.max_board_motion_diag_fraction * diag)
          throw_input_error(
              "{}: the camera moved between the board capture and {} ({:.1f} px); use a "
              "tripod and a remote release",
              board_path, reference_path, moved);
      }
      continue;
    }
    std::vector<double> moved;
    for (const auto& [corner, centre] : own) {
      auto it = reference.find(corner);
      if (it != reference.end()) moved.push_back(cv::norm(centre - it->second));
    }
    if (moved.empty()) continue;
    std::sort(moved.begin(), moved.end());
    const double median = moved[moved.size() / 2];
    // Plus a lens: the markers are seen through the lens array, whose sampling moves their
    // edges by up to a lens between patterns (a coarse sheet's lens spans several pixels).
    if (median > std::max(options.max_motion_px, options.max_motion_diag_fraction * diag) + lens_px)
      throw_input_error(
          "{}: the camera moved between the captures of position {} (the corner markers are "
          "{:.1f} px away from where {} shows them); use a tripod and a remote release",
          pc.path(stem), pc.name, median, reference_path);
  }
  if (verified < int(set.patterns.size()) - 1)
    ctx.warnings.push_back(fmt::format(
        "{}: corner markers found in only {} of {} captures; pattern identity and camera "
        "motion could not be checked for the others",
        pc.name, verified, set.patterns.size() - 1));
}

void refine_with_fringes(const PositionContext& ctx, PositionState& state) {
  // Dense registration from the fringe patterns, if the set has them: the board's ~40
  // corners leave the camera's lateral position a few millimetres uncertain, thousands of
  // fringe blocks over the whole screen pin it (and the panel mapping) down.
  if (ctx.roles.fringe_x.empty()) return;
  const sim::PositionCaptures& pc = ctx.captures;
  auto images = [&](const std::vector<const sim::PatternInfo*>& list) {
    std::vector<cv::Mat> out_images;
    for (const auto* p : list) out_images.push_back(pc.image(PatternRoles::stem(p)));
    return out_images;
  };
  auto& reg = state.registration;
  FringeDecodeOptions fringe_options;
  fringe_options.correct_exposure_drift = ctx.options.decode.correct_exposure_drift;
  fringe_options.exposure_row_gain = ctx.options.decode.exposure_row_gain;
  const FringeCorrespondences dense = decode_fringes(
      images(ctx.roles.fringe_x), images(ctx.roles.fringe_y), *reg, ctx.set, fringe_options);
  // The markers stay beside the fringe points: a coarse sheet's lens sampling moves their
  // detected corners by up to a lens (2-5 px on the 20 LPI sheet), but from the farthest
  // position, where the screen spans ~1000 fringe blocks, the fringes alone left the camera
  // 4.5 mm off and with the markers 1.6 mm (docs/calibration.md, section 3.1).
  ExtraPoints extra = state.extra;
  const size_t markers = extra.image_px.size();
  const Eigen::Vector3d camera = reg->camera_position_m();
  for (size_t k = 0; k < dense.image_px.size(); ++k) {
    // Blocks where the seen view wraps mix content a lens apart: no clean position.
    if (std::abs(ctx.shift.periods(dense.panel_px[k], camera)) > ctx.options.max_fringe_shift_periods)
      continue;
    extra.image_px.push_back(dense.image_px[k]);
    extra.panel_px.push_back(dense.panel_px[k]);
    extra.shift_px.push_back(ctx.shift.correction_px(dense.panel_px[k], camera));
  }
  PositionReport& rep = state.report;
  rep.fringe_points = long(extra.image_px.size() - markers);
  if (rep.fringe_points >= ctx.options.min_fringe_points) {
    reg.emplace(ctx.board, ctx.set, ctx.camera, state.board_shift, extra);
    state.extra = extra;
    rep.reprojection_rms_px = reg->reprojection_rms_px();
    rep.camera_m = reg->camera_position_m();
  } else {
    ctx.warnings.push_back(fmt::format(
        "{}: only {} fringe blocks decoded; registration from the board alone (less "
        "accurate center); check focus and exposure of the fringe photos",
        pc.name, rep.fringe_points));
  }
}

void refine_self_calibration(const sim::PatternSet& set, const CalibrateOptions& options,
                             const std::vector<BoardDetection>& boards,
                             const std::vector<PositionState>& states, CalibrationOutcome& out) {
  const display::DisplayCalibration& nd = set.nominal.display;
  // Through a cover layer a camera sees a panel point where its light leaves the cover
  // (cover_rays.hpp), as registration projects it: from the position's registered camera.
  Eigen::Vector3d camera_m{0, 0, 1};
  auto panel_m = [&](cv::Point2d px) {
    const Eigen::Vector3d m = uv_to_display_m(nd, panel_px_to_uv(nd, px));
    const display::Point3 e = display::cover_exit_point({m.x(), m.y(), 0.0}, {camera_m.x(), camera_m.y(), camera_m.z()},
                                      nd.cover);
    return cv::Point3f(float(e.x), float(e.y), float(e.z));
  };
  // Evenly thinned fringe points: a few hundred per position already pin the intrinsics, and
  // calibrateCamera runs three times for the focal length's uncertainty.
  constexpr size_t kMaxFringePoints = 1500;
  std::vector<PlanarView> views;
  for (size_t i = 0; i < states.size(); ++i) {
    PlanarView v;
    camera_m = states[i].registration->camera_position_m();
    const BoardDetection& b = boards[i];
    for (size_t k = 0; k < b.ids.size(); ++k) {
      v.panel_m.push_back(panel_m(set.board.corners_px.at(size_t(b.ids[k])) + states[i].board_shift.at(k)));
      v.image_px.push_back(b.image_px[k]);
    }
    const ExtraPoints& f = states[i].extra;
    const size_t stride = std::max<size_t>(1, (f.image_px.size() + kMaxFringePoints - 1) / kMaxFringePoints);
    for (size_t k = 0; k < f.image_px.size(); k += stride) {
      v.panel_m.push_back(panel_m(f.panel_px[k] + f.shift_px[k]));
      v.image_px.push_back(f.image_px[k]);
    }
    views.push_back(std::move(v));
  }
  const PlanarCalibration c = calibrate_planar_views(views, boards.at(0).image_size, &out.camera);
  out.camera = c.camera;
  out.camera_focal_sigma_rel = c.focal_sigma_rel;
  if (c.focal_sigma_rel > options.max_focal_sigma_rel)
    throw_input_error(
        "the photos do not determine the camera's focal length (uncertainty {:.0f} % with the "
        "fringe points, at most {:.0f} % usable): photograph the positions about 20 degrees to "
        "the sides of the screen's axis, or pass --camera camera.yaml from a camera calibration",
        100 * c.focal_sigma_rel, 100 * options.max_focal_sigma_rel);
}

DecodedPhase decode_position_phase(const PositionContext& ctx, PositionState& state) {
  const sim::PositionCaptures& pc = ctx.captures;
  const auto& phase_p = ctx.roles.phase;
  std::vector<cv::Mat> captures;
  for (const auto* p : phase_p) {
    const std::string stem = PatternRoles::stem(p);
    const cv::Mat& img = pc.image(stem);
    const Exposure e = exposure(img, state.screen_mask, ctx.options.saturation_level);
    if (e.clipped_fraction > ctx.options.max_clipped_fraction)
      throw_input_error("{}: over-exposed: {:.0f} % of the screen is saturated; lower the "
                        "exposure",
                        pc.path(stem), 100 * e.clipped_fraction);
    captures.push_back(img);
  }
  DecodedPhase phase = decode_phase(captures, *state.registration, ctx.set, ctx.options.decode);
  for (size_t k = 0; k < phase_p.size(); ++k)
    if (phase.step_correlation[k] < ctx.options.min_step_correlation &&
        phase.samples.size() > size_t(ctx.options.step_check_min_samples))
      throw_input_error(
          "{}: does not look like phase step {} of {} (correlation {:.2f}); was the right "
          "pattern shown?",
          pc.path(PatternRoles::stem(phase_p[k])), phase_p[k]->step, ctx.set.phase_steps,
          phase.step_correlation[k]);
  if (long(phase.samples.size()) < ctx.options.min_phase_samples)
    throw_input_error(
        "{}: only {} usable phase samples of {} screen blocks ({} saturated, {} without "
        "fringe contrast); focus on the screen, check the exposure, photograph from closer",
        pc.name, phase.samples.size(), phase.blocks_on_panel, phase.blocks_clipped,
        phase.blocks_low_modulation);
  PositionReport& rep = state.report;
  rep.samples = long(phase.samples.size());
  rep.blocks_on_panel = phase.blocks_on_panel;
  rep.blocks_clipped = phase.blocks_clipped;
  rep.blocks_low_modulation = phase.blocks_low_modulation;
  rep.median_modulation = phase.median_modulation;
  // Divided out already (calib/phasors/exposure_drift.hpp); said, because a camera that drifts this
  // much is worth fixing (manual exposure) and its white/black checks saw one exposure only.
  if (phase.exposure.max_gain_change() > ctx.options.warn_exposure_change)
    ctx.warnings.push_back(fmt::format(
        "{}: the exposure changed between the phase photos by up to {:.1f} % (measured on {} "
        "blocks without fringes and divided out); lock the camera's exposure",
        pc.name, 100 * phase.exposure.max_gain_change(), phase.exposure.reference_blocks));
  // Banding along the rows: a rolling shutter under flickering light.
  if (phase.exposure.max_row_variation() > ctx.options.warn_row_variation)
    ctx.warnings.push_back(fmt::format(
        "{}: the phase photos band along their rows by up to +-{:.1f} % (rolling shutter under "
        "flickering light; fitted and divided out); a shutter time of a whole number of flicker "
        "periods (1/50 or 1/60 s) avoids it",
        pc.name, 100 * phase.exposure.max_row_variation()));
  return phase;
}

PositionData position_data(const PositionContext& ctx, const PositionState& state,
                           const DecodedPhase& phase, bool camera_self_calibrated,
                           const std::optional<Eigen::Vector3d>& known_camera_m) {
  const PositionReport& rep = state.report;
  const display::DisplayCalibration& nd = ctx.set.nominal.display;
  PositionData pd;
  pd.name = ctx.captures.name;
  pd.samples = phase.samples;
  pd.camera_m = rep.camera_m;
  // Priors on the camera position from the registration's precision: planar pose is weak
  // laterally (rotation and translation trade off, resolved only by the perspective of the
  // board) and scales in depth with the focal length's uncertainty.
  const double z = rep.camera_m.z(), f = ctx.camera.camera_matrix(0, 0);
  const double extent = 0.5 * std::min(nd.width_m(), nd.height_m()) / z;
  const double noise =
      rep.reprojection_rms_px / std::sqrt(double(state.registration->corner_count()));
  // A self-calibrated camera's focal length is the solver's to refine (camera_per_focal_m),
  // so its uncertainty is not counted here again.
  const double focal_rel = 1e-3;
  pd.lateral_sigma_m = std::max(3e-4, 2 * z * noise / (f * extent * extent));
  pd.depth_sigma_m = std::max(focal_rel * z, 2 * z * noise / (f * extent));
  if (camera_self_calibrated) {
    // How the pose moves with the focal length: registered again through a camera 1 % longer
    // (the solver frees the focal length of a self-calibrated camera).
    constexpr double h = 0.01;
    sim::CameraIntrinsics longer = ctx.camera;
    longer.camera_matrix(0, 0) *= 1 + h;
    longer.camera_matrix(1, 1) *= 1 + h;
    const Registration moved(ctx.board, ctx.set, longer, state.board_shift, state.extra);
    pd.camera_per_focal_m = (moved.camera_position_m() - state.registration->camera_position_m()) / h;
  }
  if (known_camera_m) {
    pd.camera_m = *known_camera_m;
    pd.lateral_sigma_m = pd.depth_sigma_m = 1e-4;
  }
  return pd;
}

void add_cover_derivatives(const PositionContext& ctx, const PositionState& state, PositionData& data,
                           double step_m) {
  sim::PatternSet thicker = ctx.set;
  thicker.nominal.display.cover.thickness_m += step_m;
  const Registration& reg = *state.registration;
  const Registration moved(ctx.board, thicker, ctx.camera, state.board_shift, state.extra);
  data.camera_per_cover_m = (moved.camera_position_m() - reg.camera_position_m()) / step_m;
  // The pixel that looked at each sample's panel point, and where the thicker cover puts it.
  std::vector<display::ScreenUV> uv;
  uv.reserve(data.samples.size());
  for (const PhaseSample& s : data.samples) uv.push_back({s.u, s.v});
  std::vector<cv::Point2f> pixels;
  for (const cv::Point2d& p : reg.uv_to_image(uv)) pixels.emplace_back(float(p.x), float(p.y));
  // Both through the same round trip, so that only the cover's change is left.
  const std::vector<display::ScreenUV> here = reg.image_to_panel_uv(pixels);
  const std::vector<display::ScreenUV> there = moved.image_to_panel_uv(pixels);
  data.sample_per_cover.clear();
  data.sample_per_cover.reserve(uv.size());
  for (size_t k = 0; k < uv.size(); ++k)
    data.sample_per_cover.emplace_back(float((there[k].u - here[k].u) / step_m),
                                       float((there[k].v - here[k].v) / step_m));
}

sim::PatternSet check_colour_order(const sim::PatternSet& set, const CalibrateOptions& options,
                              const std::vector<DecodedPhase>& phases,
                              std::vector<PositionData>& data, CalibrationOutcome& out) {
  const display::DisplayCalibration& drawn = set.nominal.display;
  SubpixelLayout given = SubpixelLayout::of(drawn);
  if (options.flip_subp) given = {false, *options.flip_subp};
  std::vector<const DecodedPhase*> positions;
  for (const DecodedPhase& p : phases) positions.push_back(&p);
  out.colour_order = compare_subpixel_layouts(drawn, given, positions, options.colour_order);
  const ColourOrderCheck& check = out.colour_order;
  if (!check.refused() && !(check.best == check.given)) out.warnings.push_back(check.finding);
  for (size_t i = 0; i < data.size() && i < phases.size(); ++i)
    correct_for_layout(check, drawn, phases[i], data[i].samples);
  sim::PatternSet solved = set;
  solved.nominal.display = check.adopted.apply(drawn);
  return solved;
}

void solve_display(const sim::PatternSet& set, const std::vector<PositionData>& data,
                   const SolverOptions& options, CalibrationOutcome& out) {
  std::vector<PhasePlane> planes;
  out.coarse = coarse_start(set.nominal, data, options.fit_view_cone, &planes);
  for (size_t i = 0; i < planes.size(); ++i) out.positions[i].plane_coherence = planes[i].coherence;
  SolverOptions solver = options;
  if (out.camera_self_calibrated) solver.focal_sigma_rel = out.camera_focal_sigma_rel;
  out.solve = solve_lens(set.nominal, out.coarse, data, solver);
  if (out.camera_self_calibrated) {
    const double scale = 1 + out.solve.focal_change_rel;
    out.camera.camera_matrix(0, 0) *= scale;
    out.camera.camera_matrix(1, 1) *= scale;
    if (out.solve.sigma.count("focal_rel")) out.camera_focal_sigma_rel = out.solve.sigma.at("focal_rel");
  }
  for (size_t i = 0; i < out.positions.size(); ++i) {
    out.positions[i].camera_refined_m = out.solve.cameras_m[i];
    out.positions[i].residual_rms_periods = out.solve.position_rms[i];
  }
}

display::Calibration assemble_calibration(const sim::PatternSet& set,
                                 const std::vector<sim::PositionCaptures>& positions,
                                 const CalibrateOptions& options,
                                 const CalibrationOutcome& out) {
  const display::DisplayCalibration& nd = set.nominal.display;
  display::Calibration c;
  c.display = apply_estimate(nd, out.solve.lens);
  // A free cover's thickness is the solve's (its sigma is in the uncertainties beside it).
  if (out.solve.cover.free) c.display.cover.thickness_m = out.solve.cover.thickness_m;
  c.correction = out.solve.correction;
  if (positions.size() >= 2 && options.solver.fit_view_cone) {
    // The measured cone is the cone; the nominal stays beside it for provenance.
    c.view_cone_measured_deg = out.solve.lens.view_cone_deg;
    c.view_cone_nominal_deg = nd.view_cone_deg;
    c.display.view_cone_deg = out.solve.lens.view_cone_deg;
  } else if (set.nominal.view_cone_measured_deg) {
    // Not measurable from these photos but known (--view-cone, or a template that measured
    // it): it stands, and the cone gate passes.
    c.view_cone_measured_deg = set.nominal.view_cone_measured_deg;
    c.view_cone_nominal_deg = set.nominal.view_cone_nominal_deg;
  }
  c.uncertainty = out.solve.sigma;
  const double slope = c.display.slope;
  if (out.solve.sigma.count("slope"))
    c.uncertainty["slant_deg"] =
        out.solve.sigma.at("slope") / (1 + slope * slope) * 180 / std::numbers::pi;
  c.residuals = out.solve.residuals;
  const display::ViewCountAdvice advice = display::recommend_view_count(c);
  c.recommended_views = advice.views;
  c.view_count_rule = advice.rule;
  ojson inputs = ojson::array();
  for (const auto& pc : positions)
    for (const auto& [stem, path] : pc.paths) inputs.push_back(path);
  c.provenance = {{"tool", "lfd calibrate"},
                  {"created", iso_time_now()},
                  {"method", "ChArUco registration; K-step phase shifting in the nominal view "
                             "fraction; FFT coarse start; one Ceres problem (pitch, slope, "
                             "center, view cone, B-spline correction, camera positions)"},
                  {"positions", int(positions.size())},
                  {"phase_steps", set.phase_steps},
                  {"camera", out.camera_self_calibrated ? "self-calibrated" : "given"},
                  {"inputs", inputs}};
  return c;
}

}  // namespace lfd::calib
