#include "calib/calibrate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <numbers>
#include <array>
#include <set>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "calib/coarse_start.hpp"
#include "calib/fringe_registration.hpp"
#include "calib/display/lens_model.hpp"
#include "calib/display/lens_relations.hpp"
#include "calib/registration.hpp"
#include "calib/display/view_count.hpp"
#include "util/error.hpp"

namespace lfd::calib {

namespace {

using ojson = nlohmann::ordered_json;

cv::Mat read_capture(const std::filesystem::path& path) {
  cv::Mat raw = cv::imread(path.string(), cv::IMREAD_UNCHANGED);
  if (raw.empty()) throw_input_error("{}: not an image OpenCV can read", path.string());
  double scale = 1.0;
  switch (raw.depth()) {
    case CV_8U: scale = 1.0 / 255; break;
    case CV_16U: scale = 1.0 / 65535; break;
    case CV_32F: scale = 1.0; break;
    default: throw_input_error("{}: unsupported pixel depth", path.string());
  }
  cv::Mat rgb;
  if (raw.channels() == 1) cv::cvtColor(raw, rgb, cv::COLOR_GRAY2RGB);
  else if (raw.channels() == 3) cv::cvtColor(raw, rgb, cv::COLOR_BGR2RGB);
  else if (raw.channels() == 4) cv::cvtColor(raw, rgb, cv::COLOR_BGRA2RGB);
  else throw_input_error("{}: unsupported channel count {}", path.string(), raw.channels());
  cv::Mat out;
  rgb.convertTo(out, CV_32FC3, scale);
  return out;
}

cv::Mat to_gray8(const cv::Mat& rgb) {
  cv::Mat gray, out;
  cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
  gray.convertTo(out, CV_8U, 255.0);
  return out;
}

// Pixels of the screen in the photo (the projected panel quad, shrunk by 3 %).
cv::Mat screen_mask(const Registration& reg, cv::Size size) {
  std::vector<ScreenUV> uv = {{0.03, 0.03}, {0.97, 0.03}, {0.97, 0.97}, {0.03, 0.97}};
  std::vector<cv::Point> poly;
  for (const auto& p : reg.uv_to_image(uv)) poly.emplace_back(int(p.x), int(p.y));
  cv::Mat mask(size, CV_8U, cv::Scalar(0));
  cv::fillConvexPoly(mask, poly, cv::Scalar(255));
  return mask;
}

struct Exposure {
  double clipped_fraction = 0, mean = 0;
};

Exposure exposure(const cv::Mat& rgb, const cv::Mat& mask) {
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
      if (mx >= 0.985f) ++clipped;
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

cv::Mat to_mat(const ImageF& image) {
  cv::Mat out(image.height, image.width, CV_32FC3);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c)
        out.at<cv::Vec3f>(y, x)[c] = image.at(x, y, std::min(c, image.channels - 1));
  return out;
}

std::vector<PositionCaptures> read_captures(const std::filesystem::path& dir,
                                            const PatternSet& set,
                                            std::vector<std::string>& warnings) {
  namespace fs = std::filesystem;
  const fs::path root = dir / "captures";
  if (!fs::is_directory(root))
    throw_input_error("{}: no captures folder (save the photos as {}/<position>/<pattern file>)",
                      root.string(), root.string());
  std::vector<fs::path> position_dirs;
  for (const auto& e : fs::directory_iterator(root))
    if (e.is_directory()) position_dirs.push_back(e.path());
    else warnings.push_back(root.string() + ": ignoring " + e.path().filename().string() +
                            " (captures go into one folder per camera position)");
  std::sort(position_dirs.begin(), position_dirs.end());
  if (position_dirs.empty())
    throw_input_error("{}: no camera position folders (expected {}/<position>/...)",
                      root.string(), root.string());

  std::vector<PositionCaptures> out;
  for (const auto& pdir : position_dirs) {
    PositionCaptures pc;
    pc.name = pdir.filename().string();
    std::map<std::string, fs::path> found;
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(pdir))
      if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      const std::string stem = f.stem().string();
      if (!set.find(stem)) {
        warnings.push_back(f.string() + ": matches no pattern in the manifest; ignored");
        continue;
      }
      if (found.count(stem))
        throw_input_error("{}: two captures of pattern {} ({} and {}); keep one", pdir.string(),
                          stem, found[stem].filename().string(), f.filename().string());
      found[stem] = f;
    }
    for (const auto& p : set.patterns) {
      const std::string stem = fs::path(p.file).stem().string();
      if (!found.count(stem))
        throw_input_error("{}: missing capture of pattern {} (expected {})", pdir.string(),
                          p.file, (pdir / p.file).string());
    }
    cv::Size size;
    for (const auto& [stem, path] : found) {
      cv::Mat img = read_capture(path);
      if (size.area() && img.size() != size)
        throw_input_error("{}: is {}x{}, the other captures of position {} are {}x{}",
                          path.string(), img.cols, img.rows, pc.name, size.width, size.height);
      size = img.size();
      pc.images[stem] = img;
      pc.paths[stem] = path.string();
    }
    out.push_back(std::move(pc));
  }
  return out;
}

CalibrationOutcome calibrate_display(const PatternSet& set,
                                     const std::vector<PositionCaptures>& positions,
                                     const CalibrateOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  CalibrationOutcome out;
  const DisplayCalibration& nd = set.nominal.display;
  if (positions.empty()) throw_input_error("calibrate: no camera positions");
  auto stem_of = [](const PatternInfo* p) { return std::filesystem::path(p->file).stem().string(); };
  const PatternInfo* board_p = set.of_kind(PatternKind::kBoard).at(0);
  const auto phase_p = set.of_kind(PatternKind::kPhase);
  const auto white_p = set.of_kind(PatternKind::kWhite);
  const auto black_p = set.of_kind(PatternKind::kBlack);
  const auto fringe_x_p = set.of_kind(PatternKind::kFringeX);
  const auto fringe_y_p = set.of_kind(PatternKind::kFringeY);
  auto path_of = [](const PositionCaptures& pc, const std::string& stem) {
    auto it = pc.paths.find(stem);
    return it == pc.paths.end() ? pc.name + "/" + stem : it->second;
  };
  auto image_of = [&](const PositionCaptures& pc, const std::string& stem) -> const cv::Mat& {
    auto it = pc.images.find(stem);
    if (it == pc.images.end())
      throw_input_error("{}: missing capture of pattern {}", pc.name, stem);
    return it->second;
  };

  // 1. Boards.
  std::vector<BoardDetection> boards;
  for (const auto& pc : positions) {
    const std::string stem = stem_of(board_p);
    BoardDetection b = detect_board(to_gray8(image_of(pc, stem)), set);
    if (b.ids.size() < 8 && b.touches_border)
      throw_input_error(
          "{}: the screen is partly outside the photo (the board is cut off at the image "
          "border, {} ChArUco corners left); step back or re-aim so the whole screen shows",
          path_of(pc, stem), b.ids.size());
    if (b.ids.size() < 8)
      throw_input_error(
          "{}: no registration board found ({} ChArUco corners); show {} full screen, focus on "
          "the screen and keep all of it in the photo",
          path_of(pc, stem), b.ids.size(), board_p->file);
    boards.push_back(std::move(b));
  }

  // 2. Intrinsics.
  if (options.camera) {
    out.camera = *options.camera;
    const cv::Size s = boards[0].image_size;
    if (out.camera.width != s.width || out.camera.height != s.height)
      throw_input_error("camera intrinsics are for {}x{} images, the captures are {}x{}",
                        out.camera.width, out.camera.height, s.width, s.height);
  } else {
    double rms = 0;
    out.camera = self_calibrate(boards, set, &rms);
    out.camera_self_calibrated = true;
    if (rms > 1.0)
      out.warnings.push_back(fmt::format(
          "camera self-calibration reprojection error {:.2f} px; a --camera file from a proper "
          "camera calibration will give a more accurate center",
          rms));
  }

  // 3. Per position: registration, screen-in-photo, exposure, identity and motion, phase.
  const LensModel nominal_lens(nd, set.nominal.correction);
  std::vector<PositionData> data;
  for (size_t i = 0; i < positions.size(); ++i) {
    const auto& pc = positions[i];
    const std::string board_path = path_of(pc, stem_of(board_p));
    PositionReport rep;
    rep.name = pc.name;
    std::optional<Registration> reg;
    std::vector<cv::Point2d> board_shift;
    // The lens array shows a panel feature displaced by the lens content shift along the row
    // (lens_relations.hpp, nominal cone); this moves it back for the pose.
    auto lens_shift_periods = [&](cv::Point2d px, const Eigen::Vector3d& camera) {
      const Eigen::Vector3d p = uv_to_display_m(nd, panel_px_to_uv(nd, px));
      const double f_seen = seen_fraction(camera.x() - p.x(), camera.z() - p.z(), nd.view_cone_deg);
      return lens_content_shift(f_seen, nd.inv_view);
    };
    auto lens_shift_px = [&](cv::Point2d px, const Eigen::Vector3d& camera) {
      const double shift = lens_shift_periods(px, camera);
      return cv::Point2d(-shift / nominal_lens.pitch_periods() * nd.screen_w, 0.0);
    };
    try {
      reg.emplace(boards[i], set, out.camera);
      // The lens array shows each board corner displaced by (c - 1/2) lens periods along the
      // row (lens_relations.hpp, lens_content_shift); move the corners back for the pose.
      const Eigen::Vector3d c0 = reg->camera_position_m();
      for (int id : boards[i].ids)
        board_shift.push_back(lens_shift_px(set.board.corners_px.at(size_t(id)), c0));
      reg.emplace(boards[i], set, out.camera, board_shift);
    } catch (const InputError& e) {
      throw_input_error("{}: {}", board_path, e.what());
    }
    rep.board_corners = reg->corner_count();
    rep.reprojection_rms_px = reg->reprojection_rms_px();
    rep.camera_m = reg->camera_position_m();
    if (rep.camera_m.z() <= 0)
      throw_input_error("{}: the camera is not in front of the screen", board_path);
    const cv::Size size = boards[i].image_size;
    for (const auto& p : reg->uv_to_image({{0, 0}, {1, 0}, {1, 1}, {0, 1}}))
      if (p.x < 0 || p.y < 0 || p.x > size.width - 1 || p.y > size.height - 1)
        throw_input_error(
            "{}: the screen is partly outside the photo (a screen corner falls at pixel "
            "({:.0f}, {:.0f}) of a {}x{} image); step back or re-aim so the whole screen shows",
            board_path, p.x, p.y, size.width, size.height);
    if (rep.reprojection_rms_px > 3.0)
      out.warnings.push_back(fmt::format("{}: board reprojection error {:.2f} px (focus?)",
                                         board_path, rep.reprojection_rms_px));

    const cv::Mat mask = screen_mask(*reg, size);
    const std::string white_stem = stem_of(white_p.at(0)), black_stem = stem_of(black_p.at(0));
    const Exposure white = exposure(image_of(pc, white_stem), mask);
    const Exposure black = exposure(image_of(pc, black_stem), mask);
    if (white.clipped_fraction > options.max_clipped_fraction)
      throw_input_error(
          "{}: over-exposed: {:.0f} % of the screen is saturated; lower the exposure time or ISO "
          "(manual exposure, set on the white pattern)",
          path_of(pc, white_stem), 100 * white.clipped_fraction);
    if (white.mean - black.mean < options.min_contrast)
      throw_input_error(
          "{}: under-exposed: white and black differ by {:.1f} % of full scale; raise the "
          "exposure (manual exposure, set on the white pattern)",
          path_of(pc, white_stem), 100 * (white.mean - black.mean));
    rep.clipped_fraction = white.clipped_fraction;

    // Pattern identity and camera motion from the corner markers. A marker farther than a
    // tenth of the image from where the registration puts it is a false detection.
    std::vector<cv::Point2d> predicted_markers;
    {
      std::vector<ScreenUV> uv;
      for (const auto& c : set.markers.centres_px) uv.push_back(panel_px_to_uv(nd, c));
      predicted_markers = reg->uv_to_image(uv);
    }
    const double diag = std::hypot(size.width, size.height);
    const double lens_px = double(size.width) / nominal_lens.pitch_periods();
    std::map<int, cv::Point2d> reference;
    std::string reference_path;
    int verified = 0;
    for (const auto& p : set.patterns) {
      if (p.kind == PatternKind::kBoard) continue;
      const std::string stem = stem_of(&p);
      const auto markers = detect_corner_marker_corners(to_gray8(image_of(pc, stem)));
      std::map<int, cv::Point2d> own;
      std::set<int> others;
      for (const auto& [id, corners] : markers) {
        const cv::Point2d centre = (corners[0] + corners[1] + corners[2] + corners[3]) * 0.25;
        if (cv::norm(centre - predicted_markers[size_t(id % 4)]) > 0.1 * diag) continue;
        if (id / 4 == p.index) {
          own[id % 4] = centre;
        } else if (id / 4 < int(set.patterns.size())) {
          others.insert(id / 4);
        }
      }
      if (own.empty() && !others.empty())
        throw_input_error("{}: shows pattern {}, expected {}", path_of(pc, stem),
                          set.patterns[size_t(*others.begin())].file, p.file);
      if (own.empty()) continue;
      ++verified;
      if (reference.empty()) {
        reference = own;
        reference_path = path_of(pc, stem);
        // The board capture has no corner markers: check it against this one through the
        // registration (tolerance: a lens of apparent shift plus the pose error).
        for (const auto& [corner, centre] : own) {
          const double moved = cv::norm(predicted_markers[size_t(corner)] - centre);
          if (moved > 4.0 + lens_px + 0.01 * diag)
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
      if (median > std::max(options.max_motion_px, 0.005 * diag))
        throw_input_error(
            "{}: the camera moved between the captures of position {} (the corner markers are "
            "{:.1f} px away from where {} shows them); use a tripod and a remote release",
            path_of(pc, stem), pc.name, median, reference_path);
    }
    if (verified < int(set.patterns.size()) - 1)
      out.warnings.push_back(fmt::format(
          "{}: corner markers found in only {} of {} captures; pattern identity and camera "
          "motion could not be checked for the others",
          pc.name, verified, set.patterns.size() - 1));

    // Dense registration from the fringe patterns, if the set has them: the board's ~40
    // corners leave the camera's lateral position a few millimetres uncertain, thousands of
    // fringe blocks over the whole screen pin it (and the panel mapping) down.
    if (!fringe_x_p.empty()) {
      auto images = [&](const std::vector<const PatternInfo*>& list) {
        std::vector<cv::Mat> out_images;
        for (const auto* p : list) out_images.push_back(image_of(pc, stem_of(p)));
        return out_images;
      };
      const FringeCorrespondences dense =
          decode_fringes(images(fringe_x_p), images(fringe_y_p), *reg, set);
      ExtraPoints extra;
      const Eigen::Vector3d camera = reg->camera_position_m();
      for (size_t k = 0; k < dense.image_px.size(); ++k) {
        // Blocks where the seen view wraps mix content a lens apart: no clean position.
        if (std::abs(lens_shift_periods(dense.panel_px[k], camera)) > 0.4) continue;
        extra.image_px.push_back(dense.image_px[k]);
        extra.panel_px.push_back(dense.panel_px[k]);
        extra.shift_px.push_back(lens_shift_px(dense.panel_px[k], camera));
      }
      rep.fringe_points = long(extra.image_px.size());
      if (extra.image_px.size() >= 100) {
        reg.emplace(boards[i], set, out.camera, board_shift, extra);
        rep.reprojection_rms_px = reg->reprojection_rms_px();
        rep.camera_m = reg->camera_position_m();
      } else {
        out.warnings.push_back(fmt::format(
            "{}: only {} fringe blocks decoded; registration from the board alone (less "
            "accurate center); check focus and exposure of the fringe photos",
            pc.name, extra.image_px.size()));
      }
    }

    std::vector<cv::Mat> captures;
    for (const auto* p : phase_p) {
      const std::string stem = stem_of(p);
      const cv::Mat& img = image_of(pc, stem);
      const Exposure e = exposure(img, mask);
      if (e.clipped_fraction > options.max_clipped_fraction)
        throw_input_error("{}: over-exposed: {:.0f} % of the screen is saturated; lower the "
                          "exposure",
                          path_of(pc, stem), 100 * e.clipped_fraction);
      captures.push_back(img);
    }
    const DecodedPhase phase = decode_phase(captures, *reg, set, options.decode);
    for (size_t k = 0; k < phase_p.size(); ++k)
      if (phase.step_correlation[k] < 0.5 && phase.samples.size() > 100)
        throw_input_error(
            "{}: does not look like phase step {} of {} (correlation {:.2f}); was the right "
            "pattern shown?",
            path_of(pc, stem_of(phase_p[k])), phase_p[k]->step, set.phase_steps,
            phase.step_correlation[k]);
    const long min_samples = 500;
    if (long(phase.samples.size()) < min_samples)
      throw_input_error(
          "{}: only {} usable phase samples of {} screen blocks ({} saturated, {} without "
          "fringe contrast); focus on the screen, check the exposure, photograph from closer",
          pc.name, phase.samples.size(), phase.blocks_on_panel, phase.blocks_clipped,
          phase.blocks_low_modulation);
    rep.samples = long(phase.samples.size());
    rep.blocks_on_panel = phase.blocks_on_panel;
    rep.blocks_clipped = phase.blocks_clipped;
    rep.blocks_low_modulation = phase.blocks_low_modulation;
    rep.median_modulation = phase.median_modulation;
    PositionData pd;
    pd.name = pc.name;
    pd.samples = phase.samples;
    pd.camera_m = rep.camera_m;
    // Priors on the camera position from the registration's precision: planar pose is weak
    // laterally (rotation and translation trade off, resolved only by the perspective of the
    // board) and scales in depth with the focal length's uncertainty.
    {
      const double z = rep.camera_m.z(), f = out.camera.camera_matrix(0, 0);
      const double extent = 0.5 * std::min(nd.width_m(), nd.height_m()) / z;
      const double noise = rep.reprojection_rms_px / std::sqrt(double(reg->corner_count()));
      const double focal_rel = out.camera_self_calibrated ? 5e-3 : 1e-3;
      pd.lateral_sigma_m = std::max(3e-4, 2 * z * noise / (f * extent * extent));
      pd.depth_sigma_m = std::max(focal_rel * z, 2 * z * noise / (f * extent));
    }
    if (options.known_camera_positions_m.size() == positions.size()) {
      pd.camera_m = options.known_camera_positions_m[i];
      pd.lateral_sigma_m = pd.depth_sigma_m = 1e-4;
    }
    data.push_back(std::move(pd));
    out.positions.push_back(rep);
  }
  if (positions.size() < 2)
    out.warnings.push_back(
        "one camera position: the view cone cannot be separated from the pitch; the nominal "
        "view cone is kept (photograph from 2-3 positions at different distances)");

  // 4. Coarse start and the solve.
  std::vector<PhasePlane> planes;
  out.coarse = coarse_start(set.nominal, data, options.solver.fit_view_cone, &planes);
  for (size_t i = 0; i < planes.size(); ++i) out.positions[i].plane_coherence = planes[i].coherence;
  out.solve = solve_lens(set.nominal, out.coarse, data, options.solver);
  for (size_t i = 0; i < out.positions.size(); ++i) {
    out.positions[i].camera_refined_m = out.solve.cameras_m[i];
    out.positions[i].residual_rms_periods = out.solve.position_rms[i];
  }

  // 5. The calibration.
  Calibration& c = out.calibration;
  c.display = apply_estimate(nd, out.solve.lens);
  c.correction = out.solve.correction;
  if (positions.size() >= 2 && options.solver.fit_view_cone) {
    // The measured cone is the cone; the nominal stays beside it for provenance.
    c.view_cone_measured_deg = out.solve.lens.view_cone_deg;
    c.view_cone_nominal_deg = nd.view_cone_deg;
    c.display.view_cone_deg = out.solve.lens.view_cone_deg;
  }
  c.uncertainty = out.solve.sigma;
  const double slope = c.display.slope;
  if (out.solve.sigma.count("slope"))
    c.uncertainty["slant_deg"] =
        out.solve.sigma.at("slope") / (1 + slope * slope) * 180 / std::numbers::pi;
  c.residuals = out.solve.residuals;
  const ViewCountAdvice advice = recommend_view_count(c);
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

  // 6. Gates.
  const auto& g = options.gates;
  const auto& r = out.solve.residuals;
  auto sigma = [&](const char* key) {
    auto it = out.solve.sigma.find(key);
    return it == out.solve.sigma.end() ? INFINITY : it->second;
  };
  auto& fails = out.gate_failures;
  if (!out.solve.converged) fails.push_back("the solver did not converge");
  if (r.rms_periods > g.max_residual_rms_periods)
    fails.push_back(fmt::format("phase residual rms {:.3f} > {:.3f} lens periods: focus on the "
                                "screen, avoid glare, check the exposure",
                                r.rms_periods, g.max_residual_rms_periods));
  if (r.inlier_fraction < g.min_inlier_fraction)
    fails.push_back(fmt::format("only {:.0f} % of the phase samples fit the model (>= {:.0f} % "
                                "needed): glare, reflections or a wrong display description",
                                100 * r.inlier_fraction, 100 * g.min_inlier_fraction));
  if (sigma("pitch_lpi") / c.display.pitch_lpi > g.max_pitch_sigma_rel)
    fails.push_back(fmt::format("pitch uncertainty {:.1e} (relative) > {:.1e}: photograph the "
                                "whole screen from closer, or add positions",
                                sigma("pitch_lpi") / c.display.pitch_lpi, g.max_pitch_sigma_rel));
  if (c.uncertainty.count("slant_deg") && c.uncertainty["slant_deg"] > g.max_slant_sigma_deg)
    fails.push_back(fmt::format("slant uncertainty {:.4f} deg > {:.4f}: photograph the whole "
                                "screen, sharper",
                                c.uncertainty["slant_deg"], g.max_slant_sigma_deg));
  if (sigma("center_periods") > g.max_center_sigma_periods)
    fails.push_back(fmt::format("center uncertainty {:.4f} > {:.4f} lens periods: add camera "
                                "positions and give an accurate --camera calibration",
                                sigma("center_periods"), g.max_center_sigma_periods));
  if (c.view_cone_measured_deg && sigma("view_cone_deg") > g.max_view_cone_sigma_deg)
    fails.push_back(fmt::format("view cone uncertainty {:.2f} deg > {:.2f}: photograph from "
                                "positions at clearly different distances (e.g. 0.8x and 1.25x)",
                                sigma("view_cone_deg"), g.max_view_cone_sigma_deg));
  if (sigma("correction_rms_periods") > g.max_correction_sigma_periods &&
      !c.correction.empty())
    fails.push_back(fmt::format("correction field uncertainty {:.3f} > {:.3f} lens periods: "
                                "photograph the whole screen, in focus",
                                sigma("correction_rms_periods"), g.max_correction_sigma_periods));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

void enforce_gates(const CalibrationOutcome& outcome) {
  if (outcome.gate_failures.empty()) return;
  std::string msg = "calibration rejected by the quality gates (nothing written):";
  for (const auto& f : outcome.gate_failures) msg += "\n  - " + f;
  throw InputError(msg);
}

nlohmann::ordered_json outcome_report(const CalibrationOutcome& o) {
  ojson j;
  j["calibration"] = to_json(o.calibration);
  j["coarse_start"] = {{"pitch_lpi", o.coarse.pitch_lpi},
                       {"slope", o.coarse.slope},
                       {"center_periods", o.coarse.center_periods},
                       {"view_cone_deg", o.coarse.view_cone_deg}};
  ojson positions = ojson::array();
  for (const auto& p : o.positions)
    positions.push_back(
        {{"name", p.name},
         {"board_corners", p.board_corners},
         {"fringe_points", p.fringe_points},
         {"reprojection_rms_px", p.reprojection_rms_px},
         {"camera_m", {p.camera_m.x(), p.camera_m.y(), p.camera_m.z()}},
         {"camera_refined_m",
          {p.camera_refined_m.x(), p.camera_refined_m.y(), p.camera_refined_m.z()}},
         {"phase_samples", p.samples},
         {"blocks", {{"on_screen", p.blocks_on_panel}, {"saturated", p.blocks_clipped},
                     {"low_modulation", p.blocks_low_modulation}}},
         {"median_modulation", p.median_modulation},
         {"white_clipped_fraction", p.clipped_fraction},
         {"plane_coherence", p.plane_coherence},
         {"residual_rms_periods", p.residual_rms_periods}});
  j["positions"] = positions;
  j["camera"] = {{"self_calibrated", o.camera_self_calibrated},
                 {"fx", o.camera.camera_matrix(0, 0)},
                 {"fy", o.camera.camera_matrix(1, 1)},
                 {"cx", o.camera.camera_matrix(0, 2)},
                 {"cy", o.camera.camera_matrix(1, 2)}};
  j["solver"] = {{"seconds", o.solve.solve_seconds},
                 {"phase_noise_periods", o.solve.obs_sigma_periods},
                 {"noise_inflation", o.solve.noise_inflation},
                 {"stages", o.solve.report}};
  j["warnings"] = o.warnings;
  j["gate_failures"] = o.gate_failures;
  j["seconds"] = o.seconds;
  return j;
}

}  // namespace lfd::calib
