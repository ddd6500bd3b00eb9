#include "calib/solver/coarse_start.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include <Eigen/Dense>
#include <opencv2/core.hpp>

#include "display/lens_model.hpp"
#include "display/lens_relations.hpp"
#include "util/error.hpp"

namespace lfd::calib {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr int kGrid = 128;  // phasor grid over the screen: resolves up to 64 fringes
constexpr int kPad = 4;     // zero padding: quarter-cycle frequency bins

struct Cell {
  double u, v;
  std::complex<double> z;
};

std::complex<double> plane_sum(const std::vector<Cell>& cells, double fu, double fv) {
  std::complex<double> sum = 0;
  for (const auto& c : cells) sum += c.z * std::polar(1.0, -kTwoPi * (fu * c.u + fv * c.v));
  return sum;
}

}  // namespace

PhasePlane fit_phase_plane(const std::vector<PhaseSample>& samples) {
  PhasePlane plane;
  if (samples.empty()) return plane;
  // Bin the unit phasors onto a grid over the screen.
  std::vector<std::complex<double>> grid(size_t(kGrid) * kGrid, 0.0);
  for (const auto& s : samples) {
    const int i = std::clamp(int(s.u * kGrid), 0, kGrid - 1);
    const int j = std::clamp(int(s.v * kGrid), 0, kGrid - 1);
    grid[size_t(j) * kGrid + i] += std::polar(1.0, kTwoPi * s.psi);
  }
  std::vector<Cell> cells;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i)
      if (std::abs(grid[size_t(j) * kGrid + i]) > 0)
        cells.push_back({(i + 0.5) / kGrid, (j + 0.5) / kGrid, grid[size_t(j) * kGrid + i]});

  const int m = kGrid * kPad;
  cv::Mat padded(m, m, CV_64FC2, cv::Scalar(0, 0));
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const auto z = grid[size_t(j) * kGrid + i];
      padded.at<cv::Vec2d>(j, i) = {z.real(), z.imag()};
    }
  cv::Mat spectrum;
  cv::dft(padded, spectrum, cv::DFT_COMPLEX_OUTPUT);
  double best = -1;
  int bi = 0, bj = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const cv::Vec2d z = spectrum.at<cv::Vec2d>(j, i);
      const double p = z[0] * z[0] + z[1] * z[1];
      if (p > best) best = p, bi = i, bj = j;
    }
  // Bin k of the padded transform is k * kGrid / m cycles per unit (signed).
  auto freq = [&](int k) { return double(k < m / 2 ? k : k - m) * kGrid / m; };
  double fu = freq(bi), fv = freq(bj);

  // Refine on the cells: shrinking local grid searches of |plane_sum|.
  double step = double(kGrid) / m;
  for (int round = 0; round < 6; ++round) {
    double best_f = std::abs(plane_sum(cells, fu, fv)), bu = fu, bv = fv;
    for (int dj = -2; dj <= 2; ++dj)
      for (int di = -2; di <= 2; ++di) {
        if (!di && !dj) continue;
        const double cu = fu + di * step / 2, cv = fv + dj * step / 2;
        const double val = std::abs(plane_sum(cells, cu, cv));
        if (val > best_f) best_f = val, bu = cu, bv = cv;
      }
    fu = bu;
    fv = bv;
    step /= 3;
  }
  // Final: the phase and the coherence on the samples themselves.
  std::complex<double> sum = 0;
  for (const auto& s : samples)
    sum += std::polar(1.0, kTwoPi * (s.psi - fu * s.u - fv * s.v));
  plane.beta_u = fu;
  plane.beta_v = fv;
  plane.alpha = std::arg(sum) / kTwoPi;
  plane.alpha -= std::floor(plane.alpha);
  plane.coherence = std::abs(sum) / double(samples.size());
  return plane;
}

namespace {

// Each position's phase plane, with the nominal correction field (if the patterns were made
// with one) removed first, so what is left is a plane; s: coarse_start's sign of psi.
std::vector<PhasePlane> position_planes(const display::Calibration& nominal,
                                        const std::vector<PositionData>& positions, double s) {
  std::vector<PhasePlane> planes;
  for (const auto& p : positions) {
    std::vector<PhaseSample> flat = p.samples;
    if (!nominal.correction.empty())
      for (auto& q : flat) {
        double psi = q.psi + s * nominal.correction(q.u, q.v);
        q.psi = float(psi - std::floor(psi));
      }
    planes.push_back(fit_phase_plane(flat));
  }
  return planes;
}

// center: circular mean over positions of c_nom + s (f_seen(u = v = 0) - alpha), with the
// lens lines' tilt `lines` and k the view fraction per unit tangent.
double center_from_planes(const display::DisplayCalibration& d, const std::vector<PositionData>& positions,
                          const std::vector<PhasePlane>& planes, double s, double lines, double k) {
  const double width_m = d.width_m(), height_m = d.height_m();
  std::complex<double> sum = 0;
  for (size_t i = 0; i < positions.size(); ++i) {
    const auto& c = positions[i].camera_m;
    const double f_corner =
        display::seen_fraction_k(c.x() + 0.5 * width_m, c.y() + 0.5 * height_m, c.z(), lines, k);
    const double center = d.center_periods + s * (f_corner - planes[i].alpha);
    sum += std::polar(1.0, kTwoPi * center);
  }
  double center_periods = std::arg(sum) / kTwoPi;
  center_periods -= std::floor(center_periods);
  return center_periods;
}

}  // namespace

LensEstimate coarse_start(const display::Calibration& nominal, const std::vector<PositionData>& positions,
                          bool fit_view_cone, std::vector<PhasePlane>* planes_out) {
  const display::DisplayCalibration& d = nominal.display;
  const display::LensModel nom(d);
  const double s = d.inv_view ? 1.0 : -1.0;
  const double width_m = d.width_m();

  const std::vector<PhasePlane> planes = position_planes(nominal, positions, s);
  if (planes_out) *planes_out = planes;

  // beta_u_i = a - W_m k / Cz_i with a = s (P'_true - P'_nom): linear least squares in (a, k)
  // if the distances differ enough to separate them, else k from the nominal cone.
  double k = display::fraction_per_tan(d.view_cone_deg);
  double inv_min = 1e9, inv_max = 0;
  for (const auto& p : positions) {
    inv_min = std::min(inv_min, 1.0 / p.camera_m.z());
    inv_max = std::max(inv_max, 1.0 / p.camera_m.z());
  }
  double a = 0;
  if (fit_view_cone && positions.size() >= 2 && inv_max > 1.12 * inv_min) {
    Eigen::MatrixXd A(long(positions.size()), 2);
    Eigen::VectorXd b(long(positions.size()));
    for (size_t i = 0; i < positions.size(); ++i) {
      A(long(i), 0) = 1;
      A(long(i), 1) = -width_m / positions[i].camera_m.z();
      b(long(i)) = planes[i].beta_u;
    }
    const Eigen::Vector2d x = A.colPivHouseholderQr().solve(b);
    // Accept only a physically plausible cone (10 to 120 degrees).
    if (x[1] > display::fraction_per_tan(120.0) && x[1] < display::fraction_per_tan(10.0)) {
      a = x[0];
      k = x[1];
    } else {
      fit_view_cone = false;
    }
  }
  if (!(fit_view_cone && positions.size() >= 2 && inv_max > 1.12 * inv_min)) {
    a = 0;
    for (size_t i = 0; i < positions.size(); ++i)
      a += planes[i].beta_u + width_m * k / positions[i].camera_m.z();
    a /= double(positions.size());
  }
  // Vertical parallax adds -(H_m line_tilt) k / Cz = -(W_m tilt) k / Cz to beta_v; the
  // nominal tilt is close enough for a start.
  double beta_v = 0;
  for (size_t i = 0; i < planes.size(); ++i)
    beta_v += planes[i].beta_v + width_m * nom.tilt() * k / positions[i].camera_m.z();
  beta_v /= double(planes.size());

  const double pitch_p = nom.pitch_periods() + s * a;
  if (!(pitch_p > 0)) throw_input_error("calibration: the coarse start found no plausible pitch");
  const double tilt = (s * beta_v + nom.tilt() * nom.pitch_periods()) / pitch_p;
  LensEstimate e;
  const display::PitchSlope lens = display::pitch_slope_from_shader_terms(d.geometry(), pitch_p, tilt);
  e.slope = lens.slope;
  e.pitch_lpi = lens.pitch_lpi;
  e.view_cone_deg = display::view_cone_from_fraction_per_tan(k);
  e.center_periods = center_from_planes(d, positions, planes, s, display::line_tilt(d.geometry(), tilt), k);
  return e;
}

}  // namespace lfd::calib
