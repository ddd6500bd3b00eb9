// All Ceres cost functions of the calibration live in this one translation unit (Ceres
// templates are slow to compile).
#include "calib/lens_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include <Eigen/Dense>
#include <ceres/ceres.h>

#include "calib/display/lens_model.hpp"
#include "calib/display/lens_relations.hpp"

namespace lfd::calib {

namespace {


template <typename T>
T wrap_half(const T& x) {  // to [-0.5, 0.5): the residual of a phase known modulo 1
  return x - T(std::floor(scalar_part(x) + 0.5));
}

// The display constants the phase model needs besides the unknowns.
struct DisplayConstants {
  ScreenGeometry geometry;
  double width_m;
  double sign;  // s = +1 with invView, -1 without (DESIGN section 5 step 2)
  static DisplayConstants of(const DisplayCalibration& d) {
    return {d.geometry(), d.width_m(), d.inv_view ? 1.0 : -1.0};
  }
  // Px of a panel point at screen u, display frame (metres, origin at the screen centre).
  double panel_x_m(double u) const { return (u - 0.5) * width_m; }
};

// psi model without the correction field: f_seen(P) + s (A_true_linear(X) - A_nom(X)).
// lens = {pitch_lpi, slope, center, view_cone_deg}, cam = {Cx, Cz}.
template <typename T>
T psi_linear(const DisplayConstants& dc, const T* lens, const T* cam, double u, double v,
             double u_phys, double a_nom) {
  const ShaderTerms<T> terms = shader_terms(dc.geometry, lens[0], lens[1]);
  const T a_true = (T(u) + T(v) * terms.tilt) * terms.pitch_periods - lens[2];
  const T f_seen = seen_fraction(T(cam[0] - T(dc.panel_x_m(u_phys))), cam[1], lens[3]);
  return f_seen + T(dc.sign) * (a_true - T(a_nom));
}

struct Sample {
  double u, v, u_phys, a_nom, psi;
  BSplineWeights wu, wv;
};

// The data term. Parameter blocks: lens (4), camera (2), then the 16 control points whose
// B-spline basis covers the sample (one block each, so the Jacobian stays sparse). The
// correction field enters linearly, r = wrap(psi_obs - psi_lin - s w) / sigma, so its
// derivatives are the basis weights; the rest is differentiated with Jets.
class PhaseResidual : public ceres::CostFunction {
 public:
  PhaseResidual(const DisplayConstants& dc, const Sample& s, double inv_sigma, bool with_field)
      : dc_(dc), s_(s), inv_sigma_(inv_sigma), with_field_(with_field) {
    set_num_residuals(1);
    mutable_parameter_block_sizes()->push_back(4);
    mutable_parameter_block_sizes()->push_back(2);
    if (with_field_)
      for (int i = 0; i < 16; ++i) mutable_parameter_block_sizes()->push_back(1);
  }

  bool Evaluate(double const* const* p, double* residual, double** jacobians) const override {
    using Jet = ceres::Jet<double, 6>;
    Jet lens[4], cam[2];
    for (int i = 0; i < 4; ++i) lens[i] = Jet(p[0][i], i);
    for (int i = 0; i < 2; ++i) cam[i] = Jet(p[1][i], 4 + i);
    double w = 0;
    if (with_field_)
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) w += p[2 + 4 * b + a][0] * (s_.wu.w[a] * s_.wv.w[b]);
    const Jet model = psi_linear(dc_, lens, cam, s_.u, s_.v, s_.u_phys, s_.a_nom) + dc_.sign * w;
    const Jet r = wrap_half(Jet(s_.psi) - model) * inv_sigma_;
    residual[0] = r.a;
    if (jacobians) {
      if (jacobians[0])
        for (int i = 0; i < 4; ++i) jacobians[0][i] = r.v[i];
      if (jacobians[1])
        for (int i = 0; i < 2; ++i) jacobians[1][i] = r.v[4 + i];
      if (with_field_)
        for (int b = 0; b < 4; ++b)
          for (int a = 0; a < 4; ++a)
            if (jacobians[2 + 4 * b + a])
              jacobians[2 + 4 * b + a][0] = -dc_.sign * s_.wu.w[a] * s_.wv.w[b] * inv_sigma_;
    }
    return true;
  }

 private:
  DisplayConstants dc_;
  Sample s_;
  double inv_sigma_;
  bool with_field_;
};

// r = sum_j a_j x_j over scalar blocks: the smoothness prior and the gauge constraints.
class LinearCombination : public ceres::CostFunction {
 public:
  explicit LinearCombination(std::vector<double> a) : a_(std::move(a)) {
    set_num_residuals(1);
    for (size_t i = 0; i < a_.size(); ++i) mutable_parameter_block_sizes()->push_back(1);
  }
  bool Evaluate(double const* const* p, double* residual, double** jacobians) const override {
    residual[0] = 0;
    for (size_t i = 0; i < a_.size(); ++i) residual[0] += a_[i] * p[i][0];
    if (jacobians)
      for (size_t i = 0; i < a_.size(); ++i)
        if (jacobians[i]) jacobians[i][0] = a_[i];
    return true;
  }

 private:
  std::vector<double> a_;
};

// The registration's camera position as a prior on the refined one.
struct CameraPrior {
  double cx, cz, inv_sx, inv_sz;
  template <typename T>
  bool operator()(const T* cam, T* r) const {
    r[0] = (cam[0] - T(cx)) * inv_sx;
    r[1] = (cam[1] - T(cz)) * inv_sz;
    return true;
  }
};

// Integrals over [0, 1] of each 1D basis function B_i(t) and of B_i(t) (t - 0.5).
void basis_moments(int n, std::vector<double>& m0, std::vector<double>& m1) {
  m0.assign(size_t(n), 0);
  m1.assign(size_t(n), 0);
  const int steps = 4000;
  for (int s = 0; s < steps; ++s) {
    const double t = (s + 0.5) / steps;
    const BSplineWeights w = bspline_weights(n, t);
    for (int a = 0; a < 4; ++a) {
      m0[size_t(w.i0 + a)] += w.w[a] / steps;
      m1[size_t(w.i0 + a)] += w.w[a] * (t - 0.5) / steps;
    }
  }
}

struct Problem {
  double lens[4];
  std::vector<double> cams;    // 2 per position
  std::vector<double> coeffs;  // nx * ny
};

}  // namespace

DisplayCalibration apply_estimate(const DisplayCalibration& nominal, const LensEstimate& lens) {
  DisplayCalibration d = nominal;
  d.pitch_lpi = lens.pitch_lpi;
  d.slope = lens.slope;
  d.center_periods = lens.center_periods - std::floor(lens.center_periods);
  return d;
}

CorrectionField remove_gauge(const CorrectionField& field) {
  if (field.empty()) return field;
  // The LS plane from dense samples, then subtract it exactly: uniform cubic B-splines
  // reproduce 1 and t with coefficients 1 and the Greville abscissae (i - 1) / (n - 3).
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  const int n = 64;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      const Eigen::Vector3d row(1, u, v);
      ata += row * row.transpose();
      atb += row * field(u, v);
    }
  const Eigen::Vector3d plane = ata.ldlt().solve(atb);
  std::vector<double> c = field.coefficients();
  for (int iy = 0; iy < field.ny(); ++iy)
    for (int ix = 0; ix < field.nx(); ++ix) {
      const double gu = (ix - 1.0) / (field.nx() - 3), gv = (iy - 1.0) / (field.ny() - 3);
      c[size_t(iy) * field.nx() + ix] -= plane[0] + plane[1] * gu + plane[2] * gv;
    }
  return CorrectionField(field.nx(), field.ny(), std::move(c));
}

SolverResult solve_lens(const Calibration& nominal, const LensEstimate& start,
                        const std::vector<PositionData>& positions, const SolverOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const DisplayCalibration& nd = nominal.display;
  const DisplayConstants dc = DisplayConstants::of(nd);
  const LensModel nominal_lens(nd, nominal.correction);
  const bool with_field = options.grid_nx >= 4 && options.grid_ny >= 4;
  const int nx = with_field ? options.grid_nx : 0, ny = with_field ? options.grid_ny : 0;
  const bool fit_cone = options.fit_view_cone && positions.size() >= 2;

  Problem x;
  x.lens[0] = start.pitch_lpi;
  x.lens[1] = start.slope;
  x.lens[2] = start.center_periods;
  x.lens[3] = start.view_cone_deg;
  for (const auto& p : positions) {
    x.cams.push_back(p.camera_m.x());
    x.cams.push_back(p.camera_m.z());
  }
  x.coeffs.assign(size_t(nx) * ny, 0.0);

  // Samples: subsampled evenly to the cap; the nominal phase is a constant per sample.
  std::vector<std::vector<Sample>> samples(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    const auto& in = positions[i].samples;
    const size_t stride = std::max<size_t>(1, (in.size() + options.max_samples_per_position - 1) /
                                                  size_t(options.max_samples_per_position));
    for (size_t j = 0; j < in.size(); j += stride) {
      Sample s;
      s.u_phys = in[j].u;
      s.v = in[j].v;
      s.psi = in[j].psi;
      if (with_field) {  // the field is smooth: its weights at P serve for the content point too
        s.wu = bspline_weights(nx, s.u_phys);
        s.wv = bspline_weights(ny, s.v);
      }
      samples[i].push_back(s);
    }
  }

  // delta: each sample's content point (where A is evaluated) from its physical point and the
  // current estimate; it moves with the estimate, so it is updated between the stages.
  auto update_content_points = [&]() {
    const double pitch_p = shader_terms(dc.geometry, x.lens[0], x.lens[1]).pitch_periods;
    for (size_t i = 0; i < samples.size(); ++i)
      for (auto& s : samples[i]) {
        const double f_seen = seen_fraction(x.cams[2 * i] - dc.panel_x_m(s.u_phys),
                                            x.cams[2 * i + 1], x.lens[3]);
        s.u = s.u_phys + lens_content_shift(f_seen, nd.inv_view) / pitch_p;
        s.a_nom = nominal_lens.phase(s.u, s.v);
      }
  };
  update_content_points();

  std::vector<double> m0x, m1x, m0y, m1y;
  if (with_field) {
    basis_moments(nx, m0x, m1x);
    basis_moments(ny, m0y, m1y);
  }

  SolverResult result;
  // The wrapped residual (lens periods) of sample s of position i at the current estimate.
  auto residual_of = [&](size_t i, const Sample& s) {
    double w = 0;
    if (with_field)
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a)
          w += x.coeffs[size_t(s.wv.i0 + b) * nx + size_t(s.wu.i0 + a)] * s.wu.w[a] * s.wv.w[b];
    return wrap_half(s.psi - psi_linear(dc, x.lens, &x.cams[2 * i], s.u, s.v, s.u_phys, s.a_nom) -
                     dc.sign * w);
  };

  // The phase noise the final stage weights the samples with: the inlier RMS, inflated by how
  // much neighbouring samples share their errors (lens-scale moire, registration, what the
  // field cannot follow). For independent errors the mean of the n residuals in a screen cell
  // has variance sigma^2 / n; the measured n * mean^2 over sigma^2 is the inflation. Without
  // it the covariance would count 100k correlated samples as independent and come out several
  // times too small.
  auto effective_sigma = [&]() {
    constexpr int kCells = 16;
    double sum2 = 0, inflation_sum = 0;
    long n = 0, cells_used = 0;
    std::vector<std::pair<double, long>> cells;
    for (size_t i = 0; i < samples.size(); ++i) {
      cells.assign(kCells * kCells, {0.0, 0});
      for (const auto& s : samples[i]) {
        const double r = residual_of(i, s);
        if (std::abs(r) >= kOutlierBoundPeriods) continue;
        sum2 += r * r;
        ++n;
        const int cu = std::clamp(int(s.u_phys * kCells), 0, kCells - 1);
        const int cv = std::clamp(int(s.v * kCells), 0, kCells - 1);
        cells[size_t(cv) * kCells + cu].first += r;
        cells[size_t(cv) * kCells + cu].second += 1;
      }
      for (const auto& [sum, count] : cells)
        if (count >= 10) {
          inflation_sum += sum * sum / double(count);  // = count * mean^2
          ++cells_used;
        }
    }
    if (n < 10) return options.obs_sigma;
    const double sigma2 = sum2 / double(n);
    const double inflation = cells_used ? std::max(1.0, inflation_sum / cells_used / sigma2) : 1.0;
    result.noise_inflation = inflation;
    return std::max(1e-4, std::sqrt(sigma2 * inflation));
  };

  double obs_sigma = options.obs_sigma;
  auto build_and_solve = [&](double loss_scale, bool field_free, bool covariance) {
    ceres::Problem::Options po;
    po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(po);
    ceres::CauchyLoss loss(loss_scale / obs_sigma);
    const double inv_sigma = 1.0 / obs_sigma;
    for (size_t i = 0; i < samples.size(); ++i)
      for (const auto& s : samples[i]) {
        std::vector<double*> blocks{x.lens, &x.cams[2 * i]};
        if (with_field)
          for (int b = 0; b < 4; ++b)
            for (int a = 0; a < 4; ++a)
              blocks.push_back(&x.coeffs[size_t(s.wv.i0 + b) * nx + size_t(s.wu.i0 + a)]);
        problem.AddResidualBlock(new PhaseResidual(dc, s, inv_sigma, with_field), &loss, blocks);
      }
    for (size_t i = 0; i < positions.size(); ++i)
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<CameraPrior, 2, 2>(new CameraPrior{
              positions[i].camera_m.x(), positions[i].camera_m.z(),
              1.0 / positions[i].lateral_sigma_m, 1.0 / positions[i].depth_sigma_m}),
          nullptr, &x.cams[2 * i]);
    if (with_field) {
      auto at = [&](int ix, int iy) { return &x.coeffs[size_t(iy) * nx + ix]; };
      const double l = options.smoothness;
      for (int iy = 0; iy < ny; ++iy)
        for (int ix = 1; ix + 1 < nx; ++ix)
          problem.AddResidualBlock(new LinearCombination({l, -2 * l, l}), nullptr,
                                   {at(ix - 1, iy), at(ix, iy), at(ix + 1, iy)});
      for (int iy = 1; iy + 1 < ny; ++iy)
        for (int ix = 0; ix < nx; ++ix)
          problem.AddResidualBlock(new LinearCombination({l, -2 * l, l}), nullptr,
                                   {at(ix, iy - 1), at(ix, iy), at(ix, iy + 1)});
      for (int iy = 0; iy + 1 < ny; ++iy)
        for (int ix = 0; ix + 1 < nx; ++ix)
          problem.AddResidualBlock(new LinearCombination({l, -l, -l, l}), nullptr,
                                   {at(ix, iy), at(ix + 1, iy), at(ix, iy + 1), at(ix + 1, iy + 1)});
      // Gauge: integral of w times 1, (u - 1/2), (v - 1/2) over the screen is zero.
      std::vector<double*> all;
      for (auto& c : x.coeffs) all.push_back(&c);
      const double g = 1e4;
      for (int moment = 0; moment < 3; ++moment) {
        std::vector<double> a;
        for (int iy = 0; iy < ny; ++iy)
          for (int ix = 0; ix < nx; ++ix) {
            const double mx = moment == 1 ? m1x[size_t(ix)] * 12 : m0x[size_t(ix)];
            const double my = moment == 2 ? m1y[size_t(iy)] * 12 : m0y[size_t(iy)];
            a.push_back(g * mx * my);
          }
        problem.AddResidualBlock(new LinearCombination(a), nullptr, all);
      }
      if (!field_free)
        for (auto& c : x.coeffs) problem.SetParameterBlockConstant(&c);
    }
    if (!fit_cone) problem.SetManifold(x.lens, new ceres::SubsetManifold(4, {3}));

    ceres::Solver::Options so;
    so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    if (!ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::SUITE_SPARSE))
      so.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
    so.max_num_iterations = options.max_iterations;
    so.num_threads = options.threads;
    so.function_tolerance = 1e-10;
    so.parameter_tolerance = 1e-12;
    so.minimizer_progress_to_stdout = options.verbose;
    ceres::Solver::Summary summary;
    ceres::Solve(so, &problem, &summary);
    result.report += summary.BriefReport() + "\n";
    result.converged = summary.IsSolutionUsable();

    if (!covariance) return;
    // Uncertainties: the Gauss-Newton covariance at the solution. The samples are weighted by
    // their measured effective noise (effective_sigma) and the priors by theirs, so it needs
    // no rescaling.
    ceres::Covariance::Options co;
    co.algorithm_type = ceres::DENSE_SVD;
    co.null_space_rank = -1;
    co.min_reciprocal_condition_number = 1e-14;
    co.num_threads = options.threads;
    ceres::Covariance cov(co);
    std::vector<const double*> blocks{x.lens};
    for (auto& c : x.coeffs) blocks.push_back(&c);
    std::vector<std::pair<const double*, const double*>> pairs;
    for (size_t a = 0; a < blocks.size(); ++a)
      for (size_t b = a; b < blocks.size(); ++b) pairs.emplace_back(blocks[a], blocks[b]);
    if (!cov.Compute(pairs, &problem)) return;
    const size_t dim = 4 + x.coeffs.size();
    Eigen::MatrixXd c(dim, dim);
    if (!cov.GetCovarianceMatrix(blocks, c.data())) return;
    const char* names[4] = {"pitch_lpi", "slope", "center_periods", "view_cone_deg"};
    for (int i = 0; i < 4; ++i) result.sigma[names[i]] = std::sqrt(std::max(0.0, c(i, i)));
    if (!fit_cone) result.sigma["view_cone_deg"] = 0;
    if (with_field) {
      // RMS over the screen of the standard deviation of w.
      double sum = 0;
      const int n = 16;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const BSplineWeights wu = bspline_weights(nx, (i + 0.5) / n);
          const BSplineWeights wv = bspline_weights(ny, (j + 0.5) / n);
          Eigen::VectorXd g = Eigen::VectorXd::Zero(long(dim));
          for (int b = 0; b < 4; ++b)
            for (int a = 0; a < 4; ++a)
              g[4 + (wv.i0 + b) * nx + wu.i0 + a] = wu.w[a] * wv.w[b];
          sum += g.dot(c * g);
        }
      result.sigma["correction_rms_periods"] = std::sqrt(std::max(0.0, sum / (n * n)));
    }
  };

  // Stage 1: the linear model only, wide loss (the unmodelled warp is up to ~0.3 period).
  build_and_solve(0.2, false, false);
  update_content_points();
  // Stage 2: with the correction field.
  build_and_solve(0.1, true, false);
  update_content_points();
  // Stage 3: final robust scale, the measured noise, uncertainties.
  obs_sigma = effective_sigma();
  result.obs_sigma_periods = obs_sigma;
  build_and_solve(options.loss_scale, true, true);

  result.lens = {x.lens[0], x.lens[1], x.lens[2] - std::floor(x.lens[2]), x.lens[3]};
  if (with_field) result.correction = CorrectionField(nx, ny, x.coeffs);
  for (size_t i = 0; i < positions.size(); ++i)
    result.cameras_m.push_back({x.cams[2 * i], positions[i].camera_m.y(), x.cams[2 * i + 1]});

  // Residual statistics in lens periods.
  std::vector<double> abs_all;
  double sum2 = 0;
  long inliers = 0;
  for (size_t i = 0; i < samples.size(); ++i) {
    double pos_sum2 = 0;
    long pos_in = 0;
    auto& kept = result.position_samples.emplace_back();
    kept.reserve(samples[i].size());
    for (const auto& s : samples[i]) {
      const double r = residual_of(i, s);
      abs_all.push_back(std::abs(r));
      kept.push_back({float(s.u_phys), float(s.v), float(s.psi), float(r)});
      if (std::abs(r) < kOutlierBoundPeriods) {
        sum2 += r * r;
        pos_sum2 += r * r;
        ++inliers;
        ++pos_in;
      }
    }
    result.position_rms.push_back(pos_in ? std::sqrt(pos_sum2 / pos_in) : 1.0);
  }
  result.residuals.count = long(abs_all.size());
  if (!abs_all.empty()) {
    std::nth_element(abs_all.begin(), abs_all.begin() + abs_all.size() / 2, abs_all.end());
    result.residuals.median_abs_periods = abs_all[abs_all.size() / 2];
    result.residuals.inlier_fraction = double(inliers) / double(abs_all.size());
    result.residuals.rms_periods = inliers ? std::sqrt(sum2 / inliers) : 1.0;
  }
  result.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace lfd::calib
