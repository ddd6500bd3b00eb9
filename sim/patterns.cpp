#include "sim/patterns.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

#include "display/lens_model.hpp"
#include "sim/corner_markers.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::sim {

namespace {

using ojson = nlohmann::ordered_json;

constexpr const char* kManifestFormat = "lfd-patterns";
constexpr int kManifestVersion = 1;

PatternKind kind_from_string(const std::string& s, const std::string& where) {
  for (PatternKind k : {PatternKind::kBoard, PatternKind::kWhite, PatternKind::kBlack,
                        PatternKind::kPhase, PatternKind::kFringeX, PatternKind::kFringeY,
                        PatternKind::kProbe})
    if (s == to_string(k)) return k;
  throw_input_error("{}: patterns: unknown pattern kind '{}'", where, s);
}

// Chessboard corners of the board on the panel. The ChArUco object-point convention has
// changed between OpenCV releases, so instead of assuming it we detect the corners on a small
// rendering of the same board and snap them to the square grid.
std::vector<cv::Point2d> board_corners_on_panel(const BoardLayout& layout) {
  const int sq = 64;
  BoardLayout small = layout;
  small.square_px = sq;
  small.marker_px = int(std::lround(sq * double(layout.marker_px) / layout.square_px));
  auto board = make_board(small);
  cv::Mat img;
  const int margin = sq / 2;
  board->draw(cv::Size(layout.squares_x * sq + 2 * margin, layout.squares_y * sq + 2 * margin),
              img, margin, 1);
  std::vector<std::vector<cv::Point2f>> marker_corners;
  std::vector<int> marker_ids;
  cv::aruco::detectMarkers(img, board->dictionary, marker_corners, marker_ids);
  std::vector<cv::Point2f> corners;
  std::vector<int> ids;
  if (!marker_ids.empty())
    cv::aruco::interpolateCornersCharuco(marker_corners, marker_ids, img, board, corners, ids);
  const size_t n = size_t(layout.squares_x - 1) * size_t(layout.squares_y - 1);
  if (ids.size() != n)
    throw std::runtime_error("patterns: cannot locate the ChArUco corners of the board layout");
  std::vector<cv::Point2d> out(n);
  for (size_t i = 0; i < ids.size(); ++i) {
    // A corner between squares sits at a pixel boundary: OpenCV coordinate (k * sq - 0.5).
    const double ix = std::round((corners[i].x - margin + 0.5) / sq);
    const double iy = std::round((corners[i].y - margin + 0.5) / sq);
    out[size_t(ids[i])] = {layout.origin_x_px + ix * layout.square_px - 0.5,
                           layout.origin_y_px + iy * layout.square_px - 0.5};
  }
  return out;
}

void draw_corner_markers(const PatternSet& set, int index, Image8& image) {
  const auto& m = set.markers;
  auto dict = marker_dictionary();
  for (int corner = 0; corner < 4; ++corner) {
    cv::Mat marker;
    cv::aruco::drawMarker(dict, 4 * marker_group(index) + corner, m.side_px, marker, 1);
    const cv::Point origin = marker_origin_px(m, corner);
    const int x0 = origin.x, y0 = origin.y;
    for (int y = y0 - m.quiet_px; y < y0 + m.side_px + m.quiet_px; ++y)
      for (int x = x0 - m.quiet_px; x < x0 + m.side_px + m.quiet_px; ++x) {
        if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
        const bool inside = x >= x0 && y >= y0 && x < x0 + m.side_px && y < y0 + m.side_px;
        const uint8_t value = inside ? marker.at<uint8_t>(y - y0, x - x0) : 255;
        for (int c = 0; c < 3; ++c) image.at(x, y, c) = value;
      }
  }
}

}  // namespace

const char* to_string(PatternKind kind) {
  switch (kind) {
    case PatternKind::kBoard: return "board";
    case PatternKind::kWhite: return "white";
    case PatternKind::kBlack: return "black";
    case PatternKind::kPhase: return "phase";
    case PatternKind::kFringeX: return "fringe_x";
    case PatternKind::kFringeY: return "fringe_y";
    case PatternKind::kProbe: return "probe";
  }
  return "?";
}

cv::Ptr<cv::aruco::Dictionary> board_dictionary() {
  return cv::aruco::getPredefinedDictionary(cv::aruco::DICT_5X5_100);
}
cv::Ptr<cv::aruco::Dictionary> marker_dictionary() {
  return cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_250);
}

cv::Ptr<cv::aruco::CharucoBoard> make_board(const BoardLayout& layout) {
  return cv::aruco::CharucoBoard::create(layout.squares_x, layout.squares_y,
                                         float(layout.square_px), float(layout.marker_px),
                                         board_dictionary());
}

const PatternInfo* PatternSet::find(const std::string& stem) const {
  for (const auto& p : patterns)
    if (std::filesystem::path(p.file).stem().string() == stem) return &p;
  return nullptr;
}

std::vector<const PatternInfo*> PatternSet::of_kind(PatternKind kind) const {
  std::vector<const PatternInfo*> out;
  for (const auto& p : patterns)
    if (p.kind == kind) out.push_back(&p);
  return out;
}

bool PatternSet::under_marker(double u, double v, double margin_px) const {
  const auto& d = nominal.display;
  const double x = u * d.screen_w - 0.5, y = (1.0 - v) * d.screen_h - 0.5;
  const double half = markers.side_px / 2.0 + markers.quiet_px + margin_px;
  for (const auto& c : markers.centres_px)
    if (std::abs(x - c.x) < half && std::abs(y - c.y) < half) return true;
  return false;
}

namespace {

// The board and the corner markers: the same for every set of a screen.
void plan_layout(PatternSet& set, const PatternOptions& options) {
  const auto& d = set.nominal.display;
  const int short_px = std::min(d.screen_w, d.screen_h);
  const int long_px = std::max(d.screen_w, d.screen_h);

  // Board: squares as large as fit with half a square of white margin all round, so every
  // square spans tens of lenses and survives the lens sampling and the camera blur.
  BoardLayout& b = set.board;
  const int n_short = std::max(3, options.board_squares_short);
  b.square_px = short_px / (n_short + 1);
  const int n_long = std::max(3, (long_px - b.square_px) / b.square_px);
  b.squares_x = d.screen_w >= d.screen_h ? n_long : n_short;
  b.squares_y = d.screen_w >= d.screen_h ? n_short : n_long;
  b.marker_px = int(std::lround(0.7 * b.square_px));
  b.origin_x_px = (d.screen_w - b.squares_x * b.square_px) / 2;
  b.origin_y_px = (d.screen_h - b.squares_y * b.square_px) / 2;
  b.corners_px = board_corners_on_panel(b);

  CornerMarkers& m = set.markers;
  m.side_px = int(std::lround(0.09 * short_px));
  m.quiet_px = std::max(4, m.side_px / 4);
  const double inset = m.quiet_px + m.side_px / 2.0 - 0.5;
  m.centres_px = {{inset, inset},
                  {d.screen_w - 1 - inset, inset},
                  {d.screen_w - 1 - inset, d.screen_h - 1 - inset},
                  {inset, d.screen_h - 1 - inset}};
}

void add_pattern(PatternSet& set, std::string file, PatternKind kind, int step, int probe = 0) {
  set.patterns.push_back({std::move(file), kind, step, probe, int(set.patterns.size())});
}

void add_fringes(PatternSet& set, const PatternOptions& options) {
  const auto& d = set.nominal.display;
  const int short_px = std::min(d.screen_w, d.screen_h);
  auto add = [&](std::string file, PatternKind kind, int step) {
    add_pattern(set, std::move(file), kind, step);
  };
  if (options.fringes) {
    // A period long against the board registration's error (a few pixels, so the fringe
    // order follows from it) and against a lens, short enough for a precise phase.
    set.fringe_period_px = std::max(48, short_px / 12);
    for (const auto& [kind, axis] : {std::pair{PatternKind::kFringeX, "x"},
                                     std::pair{PatternKind::kFringeY, "y"}})
      for (int k = 0; k < set.fringe_steps; ++k)
        add(fmt::format("{:02d}_fringe_{}_{}of{}.png", int(set.patterns.size()), axis, k,
                        set.fringe_steps),
            kind, k);
  } else {
    set.fringe_steps = 0;
  }
}

void add_board_white_black(PatternSet& set) {
  add_pattern(set, "00_board.png", PatternKind::kBoard, 0);
  add_pattern(set, "01_white.png", PatternKind::kWhite, 0);
  add_pattern(set, "02_black.png", PatternKind::kBlack, 0);
}

}  // namespace

PatternSet plan_patterns(const display::Calibration& nominal, const PatternOptions& options) {
  if (options.phase_steps < 3 || options.phase_steps > 32)
    throw_input_error("patterns: phase steps must be between 3 and 32 (got {})",
                      options.phase_steps);
  PatternSet set;
  set.nominal = nominal;
  set.phase_steps = options.phase_steps;
  plan_layout(set, options);
  add_board_white_black(set);
  for (int k = 0; k < set.phase_steps; ++k)
    add_pattern(set, fmt::format("{:02d}_phase_{}of{}.png", 3 + k, k, set.phase_steps),
                PatternKind::kPhase, k);
  add_fringes(set, options);
  return set;
}

PatternSet plan_undescribed_patterns(int screen_w, int screen_h, double dpi,
                                     const PatternOptions& options, const ProbeOptions& probes) {
  PatternSet set;
  set.undescribed = true;
  set.probes = plan_lens_probes(screen_w, screen_h, dpi, probes);
  set.probe_steps = probes.steps;
  set.phase_steps = options.phase_steps;
  // The screen alone: no lens is known (the lens fields are placeholders nothing reads).
  display::DisplayCalibration& d = set.nominal.display;
  d.serial = "undescribed";
  d.screen_w = screen_w;
  d.screen_h = screen_h;
  d.dpi = dpi;
  d.check("patterns: --screen/--dpi");
  plan_layout(set, options);
  add_board_white_black(set);
  add_fringes(set, options);
  for (size_t j = 0; j < set.probes.size(); ++j)
    for (int k = 0; k < set.probe_steps; ++k)
      add_pattern(set,
                  fmt::format("{:02d}_probe_{:02d}_{}of{}.png", int(set.patterns.size()), j, k,
                              set.probe_steps),
                  PatternKind::kProbe, k, int(j));
  return set;
}

Image8 render_pattern(const PatternSet& set, const PatternInfo& pattern) {
  const auto& d = set.nominal.display;
  Image8 image(d.screen_w, d.screen_h, 3, 0);
  switch (pattern.kind) {
    case PatternKind::kBoard: {
      std::fill(image.pixels.begin(), image.pixels.end(), uint8_t(255));
      const auto& b = set.board;
      cv::Mat board_img;
      make_board(b)->draw(cv::Size(b.squares_x * b.square_px, b.squares_y * b.square_px),
                          board_img, 0, 1);
      for (int y = 0; y < board_img.rows; ++y)
        for (int x = 0; x < board_img.cols; ++x)
          for (int c = 0; c < 3; ++c)
            image.at(b.origin_x_px + x, b.origin_y_px + y, c) = board_img.at<uint8_t>(y, x);
      return image;  // the board pattern carries no corner markers
    }
    case PatternKind::kWhite:
      std::fill(image.pixels.begin(), image.pixels.end(), uint8_t(255));
      break;
    case PatternKind::kBlack:
      break;
    case PatternKind::kPhase: {
      // docs/calibration.md section 1: subpixel s shows 0.5 + 0.5 cos(2 pi (f_nom(s) - k/K)).
      const display::LensModel lens(d, set.nominal.correction);
      const double shift = double(pattern.step) / set.phase_steps;
#pragma omp parallel for schedule(static)
      for (int row = 0; row < d.screen_h; ++row)
        for (int x = 0; x < d.screen_w; ++x)
          for (int c = 0; c < 3; ++c) {
            const double f = lens.subpixel_view_fraction(x, row, c);
            const double value = 0.5 + 0.5 * std::cos(2.0 * std::numbers::pi * (f - shift));
            image.at(x, row, c) = uint8_t(std::lround(255.0 * value));
          }
      break;
    }
    case PatternKind::kProbe: {
      // sim/lens_probes.hpp: every subpixel at its place in RGB stripes.
      const LensProbe& probe = set.probes.at(size_t(pattern.probe));
      const double shift = double(pattern.step) / set.probe_steps;
      for (int row = 0; row < d.screen_h; ++row)
        for (int x = 0; x < d.screen_w; ++x)
          for (int c = 0; c < 3; ++c) {
            const double u = (x + (c + 0.5) / 3.0) / d.screen_w;
            const double v = 1.0 - (row + 0.5) / d.screen_h;
            const double t = probe.fu * u + probe.fv * v - shift;
            image.at(x, row, c) =
                uint8_t(std::lround(255.0 * (0.5 + 0.5 * std::cos(2.0 * std::numbers::pi * t))));
          }
      break;
    }
    case PatternKind::kFringeX:
    case PatternKind::kFringeY: {
      // Whole pixels (all three subpixels alike), so every view shows the same image.
      const bool along_x = pattern.kind == PatternKind::kFringeX;
      const double shift = double(pattern.step) / set.fringe_steps;
      for (int row = 0; row < d.screen_h; ++row)
        for (int x = 0; x < d.screen_w; ++x) {
          const double t = (along_x ? x : row) / set.fringe_period_px - shift;
          const auto value = uint8_t(std::lround(255.0 * (0.5 + 0.5 * std::cos(2.0 * std::numbers::pi * t))));
          for (int c = 0; c < 3; ++c) image.at(x, row, c) = value;
        }
      break;
    }
  }
  draw_corner_markers(set, pattern.index, image);
  return image;
}

namespace {

ojson points_to_json(const std::vector<cv::Point2d>& points) {
  ojson a = ojson::array();
  for (const auto& p : points) a.push_back({p.x, p.y});
  return a;
}

// Manifest sizes and indices: whole numbers in a range (nlohmann's conversion of a float such
// as 1e300 to int is undefined; found by fuzz_capture_manifest).
constexpr int kMaxPx = 100000;
int int_field(const ojson& v, const std::string& where, const std::string& field, int lo, int hi) {
  require_field(v.is_number_integer() && v.get<long long>() >= lo && v.get<long long>() <= hi,
                where, field, fmt::format("must be a whole number in {}..{}", lo, hi));
  return int(v.get<long long>());
}

std::vector<cv::Point2d> points_from_json(const ojson& a, const std::string& where,
                                          const std::string& field) {
  require_field(a.is_array(), where, field, "must be an array of [x, y]");
  std::vector<cv::Point2d> out;
  for (const auto& p : a) {
    require_field(p.is_array() && p.size() == 2 && p[0].is_number() && p[1].is_number(), where,
                  field, "must be an array of [x, y]");
    out.push_back({p[0].get<double>(), p[1].get<double>()});
  }
  return out;
}

}  // namespace

void write_pattern_set(const std::filesystem::path& dir, const PatternSet& set, bool force) {
  const auto pattern_dir = dir / "patterns";
  const auto manifest_path = pattern_dir / "manifest.json";
  guard_overwrite(manifest_path, force);
  for (const auto& p : set.patterns) write_png(pattern_dir / p.file, render_pattern(set, p));

  ojson j;
  j["format"] = kManifestFormat;
  j["version"] = kManifestVersion;
  j["nominal"] = display::to_json(set.nominal);
  if (set.undescribed) {
    j["undescribed"] = true;
    j["probe_steps"] = set.probe_steps;
    ojson probes = ojson::array();
    for (const auto& p : set.probes)
      probes.push_back({{"fu", p.fu}, {"fv", p.fv}, {"window_u", p.window_u},
                        {"window_v", p.window_v}});
    j["probes"] = probes;
  }
  j["phase_steps"] = set.phase_steps;
  j["fringe_steps"] = set.fringe_steps;
  j["fringe_period_px"] = set.fringe_period_px;
  const auto& b = set.board;
  j["board"] = {{"dictionary", "DICT_5X5_100"}, {"squares_x", b.squares_x},
                {"squares_y", b.squares_y},     {"square_px", b.square_px},
                {"marker_px", b.marker_px},     {"origin_px", {b.origin_x_px, b.origin_y_px}},
                {"corners_px", points_to_json(b.corners_px)}};
  j["corner_markers"] = {{"dictionary", "DICT_4X4_250"},
                         {"side_px", set.markers.side_px},
                         {"quiet_px", set.markers.quiet_px},
                         {"centres_px", points_to_json(set.markers.centres_px)},
                         {"ids", "4 * (pattern index mod 62) + corner (TL, TR, BR, BL)"}};
  ojson list = ojson::array();
  for (const auto& p : set.patterns) {
    ojson e = {{"file", p.file}, {"kind", to_string(p.kind)}, {"index", p.index}};
    if (p.kind == PatternKind::kPhase) {
      e["step"] = p.step;
      e["steps"] = set.phase_steps;
      e["shows"] = "0.5 + 0.5 cos(2 pi (f_nom(s) - step/steps)) per subpixel";
    }
    if (p.kind == PatternKind::kFringeX || p.kind == PatternKind::kFringeY) {
      e["step"] = p.step;
      e["steps"] = set.fringe_steps;
      e["shows"] = p.kind == PatternKind::kFringeX
                       ? "0.5 + 0.5 cos(2 pi (x / fringe_period_px - step/steps)) per pixel"
                       : "0.5 + 0.5 cos(2 pi (row / fringe_period_px - step/steps)) per pixel";
    }
    if (p.kind == PatternKind::kProbe) {
      e["probe"] = p.probe;
      e["step"] = p.step;
      e["steps"] = set.probe_steps;
      e["shows"] = "0.5 + 0.5 cos(2 pi (fu u + fv v - step/steps)) per subpixel (RGB stripes)";
    }
    list.push_back(e);
  }
  j["patterns"] = list;
  write_text_atomic(manifest_path, j.dump(2) + "\n");
}

PatternSet read_pattern_set(const std::filesystem::path& dir) {
  const auto path = dir / "patterns" / "manifest.json";
  const std::string where = path.string();
  if (!std::filesystem::exists(path))
    throw_input_error("{}: not found (run `lfd patterns --display D.json --out {}` first)",
                      where, dir.string());
  ojson j;
  try {
    j = ojson::parse(read_text_file(path));
  } catch (const nlohmann::json::exception& e) {
    throw_input_error("{}: not valid JSON ({})", where, e.what());
  }
  PatternSet set;
  try {
    require_field(j.is_object() && j.contains("format") && j["format"] == kManifestFormat, where,
                  "format", "is not \"lfd-patterns\"");
    require_field(j.contains("version") && j["version"] == kManifestVersion, where, "version",
                  "unsupported");
    require_field(j.contains("nominal"), where, "nominal", "is missing");
    set.nominal = display::parse_calibration(j["nominal"].dump(), where + ": nominal");
    set.phase_steps = int_field(j.value("phase_steps", ojson(0)), where, "phase_steps", 3, 32);
    set.undescribed = j.contains("undescribed");
    if (set.undescribed) {
      require_field(j["undescribed"] == true, where, "undescribed", "must be true if present");
      set.probe_steps = int_field(j.value("probe_steps", ojson(0)), where, "probe_steps", 3, 32);
      const auto& probes = j.at("probes");
      require_field(probes.is_array() && !probes.empty() && probes.size() <= 200, where,
                    "probes", "must be an array of 1..200 probes");
      for (const auto& e : probes) {
        LensProbe p;
        double* fields[] = {&p.fu, &p.fv, &p.window_u, &p.window_v};
        const char* names[] = {"fu", "fv", "window_u", "window_v"};
        for (int i = 0; i < 4; ++i) {
          require_field(e.contains(names[i]) && e[names[i]].is_number(), where,
                        std::string("probes.") + names[i], "must be a number");
          *fields[i] = e[names[i]].get<double>();
          require_field(std::isfinite(*fields[i]) && std::abs(*fields[i]) <= 1e5 &&
                            (i < 2 || *fields[i] > 0),
                        where, std::string("probes.") + names[i],
                        i < 2 ? "must be finite, at most 1e5" : "must be positive, at most 1e5");
        }
        set.probes.push_back(p);
      }
    }
    // Manifests written before the fringe patterns existed have none: board-only registration.
    set.fringe_steps = int_field(j.value("fringe_steps", ojson(0)), where, "fringe_steps", 0, 32);
    require_field(!j.contains("fringe_period_px") || j["fringe_period_px"].is_number(), where,
                  "fringe_period_px", "must be a number");
    set.fringe_period_px = j.value("fringe_period_px", 0.0);
    require_field(set.fringe_steps == 0 || set.fringe_steps >= 3, where, "fringe_steps",
                  "must be 0 or between 3 and 32");
    require_field(set.fringe_steps == 0 || (std::isfinite(set.fringe_period_px) &&
                                            set.fringe_period_px >= 8),
                  where, "fringe_period_px", "must be at least 8");
    const auto& b = j.at("board");
    set.board.squares_x = int_field(b.at("squares_x"), where, "board.squares_x", 2, 100);
    set.board.squares_y = int_field(b.at("squares_y"), where, "board.squares_y", 2, 100);
    set.board.square_px = int_field(b.at("square_px"), where, "board.square_px", 2, kMaxPx);
    set.board.marker_px =
        int_field(b.at("marker_px"), where, "board.marker_px", 1, set.board.square_px - 1);
    set.board.origin_x_px =
        int_field(b.at("origin_px").at(0), where, "board.origin_px", -kMaxPx, kMaxPx);
    set.board.origin_y_px =
        int_field(b.at("origin_px").at(1), where, "board.origin_px", -kMaxPx, kMaxPx);
    set.board.corners_px = points_from_json(b.at("corners_px"), where, "board.corners_px");
    const auto& m = j.at("corner_markers");
    set.markers.side_px = int_field(m.at("side_px"), where, "corner_markers.side_px", 0, kMaxPx);
    set.markers.quiet_px =
        int_field(m.at("quiet_px"), where, "corner_markers.quiet_px", 0, kMaxPx);
    set.markers.centres_px = points_from_json(m.at("centres_px"), where, "corner_markers");
    for (const auto& e : j.at("patterns")) {
      PatternInfo p;
      p.file = e.at("file").get<std::string>();
      p.kind = kind_from_string(e.at("kind").get<std::string>(), where);
      p.index = int_field(e.at("index"), where, "patterns.index", 0, 1000);
      p.step = int_field(e.value("step", ojson(0)), where, "patterns.step", 0, 31);
      p.probe = int_field(e.value("probe", ojson(0)), where, "patterns.probe", 0,
                          std::max(0, int(set.probes.size()) - 1));
      require_field(p.kind != PatternKind::kProbe || set.undescribed, where, "patterns",
                    "a probe pattern in a set that is not undescribed");
      set.patterns.push_back(p);
    }
  } catch (const nlohmann::json::exception& e) {
    throw_input_error("{}: malformed manifest ({})", where, e.what());
  }
  require_field(set.markers.centres_px.size() == 4, where, "corner_markers.centres_px",
                "needs 4 points");
  require_field(set.of_kind(PatternKind::kBoard).size() == 1, where, "patterns",
                "needs exactly one board pattern");
  if (set.undescribed) {
    require_field(set.of_kind(PatternKind::kPhase).empty(), where, "patterns",
                  "an undescribed set has probes, no phase patterns");
    require_field(set.of_kind(PatternKind::kProbe).size() ==
                      set.probes.size() * size_t(set.probe_steps),
                  where, "patterns", "needs probe_steps patterns of every probe");
  } else {
    require_field(int(set.of_kind(PatternKind::kPhase).size()) == set.phase_steps, where,
                  "patterns", "needs phase_steps phase patterns");
  }
  for (PatternKind kind : {PatternKind::kFringeX, PatternKind::kFringeY})
    require_field(int(set.of_kind(kind).size()) == set.fringe_steps, where, "patterns",
                  fmt::format("needs fringe_steps {} patterns", to_string(kind)));
  return set;
}

}  // namespace lfd::sim
