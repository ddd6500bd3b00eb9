#include "calib/lens_probes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "calib/registration/registration.hpp"
#include "display/lens_relations.hpp"
#include "util/error.hpp"

namespace lfd::calib {

namespace {

// Panel pixels (OpenCV coordinates) -> photo pixels, from the board's corners (seen through
// the lenses, each up to half a lens off: enough for a Fourier transform over the screen).
cv::Mat board_homography(const sim::PatternSet& set, const sim::PositionCaptures& pc,
                         const ProbeMeasureOptions& options) {
  const std::string stem = std::filesystem::path(set.of_kind(sim::PatternKind::kBoard)[0]->file).stem();
  const BoardDetection board = detect_board(sim::to_gray8(pc.image(stem)), set);
  if (int(board.ids.size()) < options.min_board_corners)
    throw_input_error("{}: no board ({} corners found, {} needed): not a photo of this screen's "
                      "board pattern, or out of focus",
                      pc.path(stem), board.ids.size(), options.min_board_corners);
  std::vector<cv::Point2f> panel;
  for (int id : board.ids) panel.emplace_back(set.board.corners_px.at(size_t(id)));
  cv::Mat h = cv::findHomography(panel, board.image_px, cv::RANSAC, 3.0);
  if (h.empty()) throw_input_error("{}: the board's corners fit no screen", pc.path(stem));
  const auto& d = set.nominal.display;
  std::vector<cv::Point2f> corners{{-0.5f, -0.5f}, {d.screen_w - 0.5f, -0.5f},
                                   {d.screen_w - 0.5f, d.screen_h - 0.5f}, {-0.5f, d.screen_h - 0.5f}};
  std::vector<cv::Point2f> seen;
  cv::perspectiveTransform(corners, seen, h);
  const cv::Rect2f photo(0, 0, float(board.image_size.width), float(board.image_size.height));
  for (const auto& c : seen)
    if (!photo.contains(c))
      throw_input_error("{}: the screen reaches outside the photo: the whole screen must be in "
                        "every photo",
                        pc.path(stem));
  return h;
}

// A probe photo must show its own corner markers (another pattern's are a mix-up).
void check_markers(const sim::PositionCaptures& pc, const sim::PatternSet& set,
                   const sim::PatternInfo& p, const std::string& stem) {
  int own = 0, other = -1;
  for (const auto& [id, centre] : detect_corner_markers(sim::to_gray8(pc.image(stem))))
    (id / 4 == sim::marker_group(p.index) ? own : other) += 1;
  if (own == 0 && other >= 0)
    throw_input_error("{}: shows other corner markers than pattern {}'s: a photo of another "
                      "pattern or another screen",
                      pc.path(stem), p.file);
}

struct Grid {
  int nu = 0, nv = 0;
};

// Each colour channel's phasor sum_k I_k exp(2 pi i k / K) on a nu x nv grid over the screen
// (column i at u = (i + 1/2) / nu, row j at v = 1 - (j + 1/2) / nv), under a Hann window,
// zero under the corner markers: three CV_32FC2 matrices, R G B.
std::array<cv::Mat, 3> screen_phasors(const std::vector<cv::Mat>& photos,
                                      const cv::Mat& panel_to_photo, const sim::PatternSet& set,
                                      Grid grid) {
  const int steps = int(photos.size());
  const auto& d = set.nominal.display;
  // grid -> panel pixels -> photo
  const cv::Matx33d to_panel(double(d.screen_w) / grid.nu, 0, 0.5 * d.screen_w / grid.nu - 0.5,
                             0, double(d.screen_h) / grid.nv, 0.5 * d.screen_h / grid.nv - 0.5,
                             0, 0, 1);
  const cv::Mat m = panel_to_photo * cv::Mat(to_panel);
  cv::Mat window(grid.nv, grid.nu, CV_32F);
  const double margin = 0.5 * set.markers.side_px;
  for (int j = 0; j < grid.nv; ++j)
    for (int i = 0; i < grid.nu; ++i) {
      const double u = (i + 0.5) / grid.nu, v = 1.0 - (j + 0.5) / grid.nv;
      const double su = std::sin(std::numbers::pi * u), sv = std::sin(std::numbers::pi * v);
      window.at<float>(j, i) = set.under_marker(u, v, margin) ? 0.0f : float(su * su * sv * sv);
    }
  std::array<cv::Mat, 3> out;
  for (int c = 0; c < 3; ++c) {
    cv::Mat re = cv::Mat::zeros(photos[0].size(), CV_32F), im = re.clone();
    for (int k = 0; k < steps; ++k) {
      cv::Mat channel;
      cv::extractChannel(photos[size_t(k)], channel, c);
      const double a = 2.0 * std::numbers::pi * k / steps;
      re += channel * std::cos(a);
      im += channel * std::sin(a);
    }
    cv::Mat re_s, im_s;
    cv::warpPerspective(re, re_s, m, {grid.nu, grid.nv}, cv::INTER_LINEAR | cv::WARP_INVERSE_MAP);
    cv::warpPerspective(im, im_s, m, {grid.nu, grid.nv}, cv::INTER_LINEAR | cv::WARP_INVERSE_MAP);
    cv::merge(std::vector<cv::Mat>{re_s.mul(window), im_s.mul(window)}, out[size_t(c)]);
  }
  return out;
}

// The channels' phasors summed as the subpixels of `bgr` stripes show them. The probe was drawn
// for RGB stripes; on a BGR panel red sits at x + 5/6 showing the grating's value for x + 1/6
// (two thirds of a pixel behind) and blue the reverse: turning each channel's phase back puts
// every channel's grating where it is seen, so the images of the grating a pixel lattice away
// cancel in the sum, as they do for RGB stripes drawn as RGB.
cv::Mat summed_phasor(const std::array<cv::Mat, 3>& channels, bool bgr, double fu, int screen_w) {
  cv::Mat sum = channels[1].clone();
  for (int c : {0, 2}) {
    const double turn = bgr ? (c == 0 ? 1.0 : -1.0) * 2.0 * std::numbers::pi * fu * (2.0 / 3.0) / screen_w : 0.0;
    const float cs = float(std::cos(turn)), sn = float(std::sin(turn));
    sum.forEach<cv::Vec2f>([&](cv::Vec2f& z, const int* pos) {
      const cv::Vec2f w = channels[size_t(c)].at<cv::Vec2f>(pos[0], pos[1]);
      z += cv::Vec2f(w[0] * cs - w[1] * sn, w[0] * sn + w[1] * cs);
    });
  }
  return sum;
}

// One probe's spectrum: DFT bin (a, b) of the grid is the wave exp(2 pi i (a u - b v)), so a
// moire (u, v) in cycles per screen width, height sits at bin (u, -v). Magnitudes over the
// median of the probe's window.
struct ProbeSpectrum {
  cv::Mat strength;  // CV_32F, nv x nu
  int wu = 0, wv = 0;  // the window, bins

  double at(int a, int b) const {
    return strength.at<float>((b % strength.rows + strength.rows) % strength.rows,
                              (a % strength.cols + strength.cols) % strength.cols);
  }
  bool in_window(double u, double v) const {
    return std::abs(u) <= wu && std::abs(v) <= wv && u * u + v * v > 4.0;
  }
  // The strongest bin within `tol` bins of moire (u, v), refined to a fraction of a bin (a
  // parabola through the log strengths: a Gaussian peak under the window).
  ProbePeak near(double u, double v, int tol) const {
    const int a0 = int(std::lround(u)), b0 = int(std::lround(-v));
    double best = -1;
    int ba = a0, bb = b0;
    for (int b = b0 - tol; b <= b0 + tol; ++b)
      for (int a = a0 - tol; a <= a0 + tol; ++a)
        if (at(a, b) > best) best = at(a, b), ba = a, bb = b;
    auto vertex = [](double l, double c, double r) {
      const double den = l - 2 * c + r;
      return den < 0 ? std::clamp(0.5 * (l - r) / den, -0.5, 0.5) : 0.0;
    };
    auto lg = [&](int a, int b) { return std::log(at(a, b) + 1e-30); };
    ProbePeak p;
    p.moire_u = ba + vertex(lg(ba - 1, bb), lg(ba, bb), lg(ba + 1, bb));
    p.moire_v = -(bb + vertex(lg(ba, bb - 1), lg(ba, bb), lg(ba, bb + 1)));
    p.strength = best;
    return p;
  }
};

ProbeSpectrum probe_spectrum(const cv::Mat& phasor, const sim::LensProbe& probe) {
  cv::Mat spectrum;
  cv::dft(phasor, spectrum, cv::DFT_COMPLEX_OUTPUT);
  std::vector<cv::Mat> parts;
  cv::split(spectrum, parts);
  ProbeSpectrum s;
  cv::magnitude(parts[0], parts[1], s.strength);
  s.wu = std::min(int(probe.window_u), s.strength.cols / 2 - 2);
  s.wv = std::min(int(probe.window_v), s.strength.rows / 2 - 2);
  std::vector<float> values;
  for (int b = -s.wv; b <= s.wv; ++b)
    for (int a = -s.wu; a <= s.wu; ++a) values.push_back(float(s.at(a, b)));
  std::nth_element(values.begin(), values.begin() + long(values.size() / 2), values.end());
  s.strength /= std::max(double(values[values.size() / 2]), 1e-12);
  return s;
}

// The local maxima of a probe's window, strongest first.
std::vector<ProbePeak> local_peaks(const ProbeSpectrum& s, double min_strength, size_t count) {
  std::vector<ProbePeak> out;
  for (int b = -s.wv; b <= s.wv; ++b)
    for (int a = -s.wu; a <= s.wu; ++a) {
      const double m = s.at(a, b);
      if (m < min_strength || !s.in_window(a, -b)) continue;
      bool top = true;
      for (int db = -1; db <= 1 && top; ++db)
        for (int da = -1; da <= 1; ++da)
          if ((da || db) && s.at(a + da, b + db) > m) top = false;
      if (top) out.push_back(s.near(a, -b, 0));
    }
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.strength > y.strength; });
  if (out.size() > count) out.resize(count);
  return out;
}

// Every way a probe's photo shows the lens g = (P', P' tilt): the lens shows the grating one
// period in m, so a moire sits at (Fu, Fv) - m g (the images of the grating a pixel lattice
// away, which a subpixel order other than RGB leaves, are weaker and not read).
struct Order {
  int a, b, m;
};
std::vector<Order> orders() { return {{0, 0, 1}, {0, 0, 2}}; }

}  // namespace

namespace {

struct Hypothesis {
  double pu = 0, pv = 0;  // g
  double score = 0;
  bool bgr = false;
  ProbePeak best;        // its strongest peak, with the lens it implies
};

// How well the lens g explains every probe: the sum over probes of the strongest peak it
// predicts there (each over its window's median, less the median itself).
Hypothesis score(double pu, double pv, const sim::PatternSet& set,
                 const std::vector<ProbeSpectrum>& spectra, int tol) {
  const auto& d = set.nominal.display;
  Hypothesis h{pu, pv, 0, {}};
  for (size_t j = 0; j < spectra.size(); ++j) {
    const auto& probe = set.probes[j];
    double best = 0;
    for (const Order& o : orders()) {
      const double u = probe.fu + o.a * d.screen_w - o.m * pu;
      const double v = probe.fv + o.b * d.screen_h - o.m * pv;
      if (!spectra[j].in_window(u, v)) continue;
      ProbePeak p = spectra[j].near(u, v, tol);
      if (p.strength <= best) continue;
      best = p.strength;
      if (p.strength > h.best.strength) {
        p.probe = int(j);
        p.pitch_periods = (probe.fu + o.a * d.screen_w - p.moire_u) / o.m;
        p.tilt_periods = (probe.fv + o.b * d.screen_h - p.moire_v) / o.m;
        h.best = p;
      }
    }
    h.score += std::max(0.0, best - 1.0);
  }
  return h;
}

}  // namespace

ProbeLensEstimate measure_lens_from_probes(const sim::PatternSet& set,
                                           const sim::PositionCaptures& pc,
                                           const ProbeMeasureOptions& options) {
  if (!set.undescribed || set.probes.empty())
    throw_input_error("calibrate: the pattern set has no lens probes");
  const cv::Mat h = board_homography(set, pc, options);
  // The grid resolves what the photo does: as many cells as photo pixels across the screen.
  const auto& d = set.nominal.display;
  std::vector<cv::Point2f> ends{{-0.5f, d.screen_h / 2.0f}, {d.screen_w - 0.5f, d.screen_h / 2.0f},
                                {d.screen_w / 2.0f, -0.5f}, {d.screen_w / 2.0f, d.screen_h - 0.5f}};
  std::vector<cv::Point2f> seen;
  cv::perspectiveTransform(ends, seen, h);
  const Grid grid{cv::getOptimalDFTSize(int(std::ceil(cv::norm(seen[1] - seen[0])))),
                  cv::getOptimalDFTSize(int(std::ceil(cv::norm(seen[3] - seen[2]))))};

  ProbeLensEstimate out;
  out.position = pc.name;
  std::vector<std::array<cv::Mat, 3>> phasors;
  for (size_t j = 0; j < set.probes.size(); ++j) {
    std::vector<cv::Mat> photos(size_t(set.probe_steps));
    for (const auto& p : set.patterns) {
      if (p.kind != sim::PatternKind::kProbe || p.probe != int(j)) continue;
      const std::string stem = std::filesystem::path(p.file).stem();
      check_markers(pc, set, p, stem);
      photos[size_t(p.step)] = pc.image(stem);
    }
    phasors.push_back(screen_phasors(photos, h, set, grid));
  }
  // Hypotheses: every way each probe's strongest peaks could show a lens in the range asked
  // for, under either subpixel order; the one that explains the most of every probe's
  // spectrum wins.
  const double aspect = double(d.screen_h) / d.screen_w;
  double p_lo = 1e300, p_hi = 0, max_tilt = 0;
  for (const auto& p : set.probes) {
    p_lo = std::min(p_lo, 0.9 * (p.fu - p.window_u));
    p_hi = std::max(p_hi, 1.1 * (p.fu + p.window_u));
    max_tilt = std::max(max_tilt, std::abs(p.fv) + p.window_v);
  }
  Hypothesis best;
  for (bool bgr : {false, true}) {
    std::vector<ProbeSpectrum> spectra;
    for (size_t j = 0; j < set.probes.size(); ++j)
      spectra.push_back(probe_spectrum(
          summed_phasor(phasors[j], bgr, set.probes[j].fu, d.screen_w), set.probes[j]));
    for (size_t j = 0; j < spectra.size(); ++j) {
      const auto& probe = set.probes[j];
      const auto peaks = local_peaks(spectra[j], options.min_strength, 3);
      if (!bgr) {
        ProbePeak strongest;
        if (!peaks.empty()) strongest = peaks.front();
        strongest.probe = int(j);
        out.peaks.push_back(strongest);
      }
      for (const auto& peak : peaks)
        for (const Order& o : orders()) {
          const double pu = (probe.fu + o.a * d.screen_w - peak.moire_u) / o.m;
          const double pv = (probe.fv + o.b * d.screen_h - peak.moire_v) / o.m;
          if (pu < p_lo || pu > p_hi || std::abs(pv) > max_tilt + 2 ||
              std::abs(pv) > pu * aspect * 2)
            continue;
          Hypothesis hyp = score(pu, pv, set, spectra, 2);
          hyp.bgr = bgr;
          if (hyp.score > best.score) best = hyp;
        }
    }
  }
  out.chosen = best.best;
  if (best.score <= 0 || out.chosen.strength < options.min_strength || out.chosen.pitch_periods <= 0)
    throw_input_error(
        "{}: no lens in the probe photos (strongest moire {:.1f} times its surroundings, {:.0f} "
        "needed): photos of a screen without the lens sheet, of another screen, or out of focus",
        pc.name, out.chosen.strength, options.min_strength);
  out.bgr = best.bgr;
  out.score = best.score;
  out.pitch_periods = out.chosen.pitch_periods;
  // A slant under 1e-6 of a period over the height is vertical: the slope must stay finite.
  const double tilt_periods = std::abs(out.chosen.tilt_periods) < 1e-6 ? 1e-6 : out.chosen.tilt_periods;
  out.tilt = tilt_periods / out.pitch_periods;
  const auto ps = display::pitch_slope_from_shader_terms(d.geometry(), out.pitch_periods, out.tilt);
  out.pitch_lpi = ps.pitch_lpi;
  out.slope = ps.slope;
  out.slant_deg = display::slant_deg_of_slope(ps.slope);
  return out;
}

}  // namespace lfd::calib
