// All Ceres cost functions of the calibration live in this one translation unit (Ceres
// templates are slow to compile): the hand-differentiated ones in phase_model.hpp (which
// their gradient-check test includes too), the auto-differentiated priors here.
#include "calib/solver/lens_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>

#include <Eigen/Dense>
#include <ceres/ceres.h>
#include <fmt/format.h>

#include "display/lens_model.hpp"
#include "display/lens_relations.hpp"
#include "calib/solver/phase_model.hpp"
#include "calib/solver/residual_statistics.hpp"

namespace lfd::calib {

using namespace phase_model;  // the costs and the model they share with the tests

namespace {

// The registration's camera position as a prior on the refined one. Per position the data
// fix only Cx + Cy line_tilt (both shift f_seen uniformly), so the prior splits the two. The
// registered position moves with the camera's focal length (`focal`: its relative change,
// held at 0 for a known camera) along d = d camera / (df / f), and with the cover's thickness
// (`cover`: its change, held at 0 unless free) along e = d camera / dt.
struct CameraPrior {
  double cx, cy, cz, dx, dy, dz, ex, ey, ez, inv_sxy, inv_sz;
  template <typename T>
  bool operator()(const T* cam, const T* focal, const T* cover, T* r) const {
    r[0] = (cam[0] - T(cx) - focal[0] * dx - cover[0] * ex) * inv_sxy;
    r[1] = (cam[1] - T(cy) - focal[0] * dy - cover[0] * ey) * inv_sxy;
    r[2] = (cam[2] - T(cz) - focal[0] * dz - cover[0] * ez) * inv_sz;
    return true;
  }
};


// A zero-mean prior on a scalar's change: the camera calibration's focal length on its
// relative change, the cover's given thickness on its change.
struct ChangePrior {
  double inv_sigma;
  template <typename T>
  bool operator()(const T* focal, T* r) const {
    r[0] = focal[0] * inv_sigma;
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
    const display::BSplineWeights w = display::bspline_weights(n, t);
    for (int a = 0; a < 4; ++a) {
      m0[size_t(w.i0 + a)] += w.w[a] / steps;
      m1[size_t(w.i0 + a)] += w.w[a] * (t - 0.5) / steps;
    }
  }
}

}  // namespace

display::DisplayCalibration apply_estimate(const display::DisplayCalibration& nominal, const LensEstimate& lens) {
  display::DisplayCalibration d = nominal;
  d.pitch_lpi = lens.pitch_lpi;
  d.slope = lens.slope;
  d.center_periods = lens.center_periods - std::floor(lens.center_periods);
  return d;
}

namespace {

// One lens problem (the unknowns, the samples) and the steps that solve it:
//   update_content_points -> solve_stage (linear model) -> solve_stage (with the field)
//   -> measure_noise -> solve_stage (final loss, measured noise) -> covariance -> statistics.
class LensProblem {
 public:
  LensProblem(const display::Calibration& nominal, const LensEstimate& start,
              const std::vector<PositionData>& positions, const SolverOptions& options)
      : nominal_(nominal.display),
        dc_(DisplayConstants::of(nominal.display, options.vertical_parallax)),
        nominal_lens_(nominal.display, nominal.correction),
        positions_(positions),
        options_(options),
        with_field_(options.grid_nx >= 4 && options.grid_ny >= 4),
        nx_(with_field_ ? options.grid_nx : 0),
        ny_(with_field_ ? options.grid_ny : 0),
        fit_cone_(options.fit_view_cone && positions.size() >= 2),
        fit_focal_(options.focal_sigma_rel > 0),
        fit_cover_(options.cover_sigma_m > 0),
        nominal_du_(display::shader_terms(dc_.geometry, nominal_.pitch_lpi, nominal_.slope).pitch_periods),
        nominal_dv_(nominal_du_ * display::shader_terms(dc_.geometry, nominal_.pitch_lpi, nominal_.slope).tilt),
        obs_sigma_(options.obs_sigma) {
    lens_[0] = start.pitch_lpi;
    lens_[1] = start.slope;
    lens_[2] = start.center_periods;
    lens_[3] = start.view_cone_deg;
    for (const auto& p : positions) {
      cams_.push_back(p.camera_m.x());
      cams_.push_back(p.camera_m.y());
      cams_.push_back(p.camera_m.z());
    }
    coeffs_.assign(size_t(nx_) * ny_, 0.0);
    select_samples();
    if (with_field_) {
      basis_moments(nx_, m0x_, m1x_);
      basis_moments(ny_, m0y_, m1y_);
    }
  }

  // Each sample's content point (where A is evaluated) from its physical point and the
  // current estimate: it moves with the estimate, so it is updated between the stages.
  void update_content_points() {
    const display::ShaderTerms<double> terms = display::shader_terms(dc_.geometry, lens_[0], lens_[1]);
    const double dt = cover_[0];
    for (size_t i = 0; i < samples_.size(); ++i)
      for (auto& s : samples_[i]) {
        const double f_seen = dc_.seen(&cams_[3 * i], s.u_phys + dt * s.du_dt, s.v + dt * s.dv_dt,
                                       terms.tilt, lens_[3], dt);
        s.u = s.u_phys + display::lens_content_shift(f_seen, nominal_.inv_view) / terms.pitch_periods;
        s.a_nom = nominal_lens_.phase(s.u, s.v);
        // The field is part of the phase at the content point, like the rest of A: at the
        // physical point it would be off by dw/du times the shift (up to half a lens), a
        // pattern that follows f_seen over the screen.
        if (with_field_) s.wu = display::bspline_weights(nx_, s.u);
      }
  }

  // Builds the Ceres problem at the current estimate and solves it under a Cauchy loss of
  // `loss_scale` lens periods; the field is held fixed unless `field_free`.
  void solve_stage(double loss_scale, bool field_free, SolverResult& result) {
    problem_ = std::make_unique<ceres::Problem>(problem_options());
    loss_ = std::make_unique<ceres::CauchyLoss>(loss_scale / obs_sigma_);
    add_phase_residuals();
    add_camera_priors();
    if (with_field_) {
      add_smoothness_prior();
      add_gauge_constraints();
      if (!field_free)
        for (auto& c : coeffs_) problem_->SetParameterBlockConstant(&c);
    }
    if (!fit_cone_) problem_->SetManifold(lens_, new ceres::SubsetManifold(4, {3}));
    add_cover_prior();

    ceres::Solver::Options so;
    so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    if (!ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::SUITE_SPARSE))
      so.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
    so.max_num_iterations = options_.max_iterations;
    so.num_threads = options_.threads;
    so.function_tolerance = options_.function_tolerance;
    so.parameter_tolerance = options_.parameter_tolerance;
    so.minimizer_progress_to_stdout = options_.verbose;
    ceres::Solver::Summary summary;
    ceres::Solve(so, problem_.get(), &summary);
    result.report += summary.BriefReport() + "\n";
    // IsSolutionUsable() is also true at the iteration limit: only CONVERGENCE (a tolerance
    // met) says the minimum was reached.
    result.converged = summary.termination_type == ceres::CONVERGENCE;
    result.termination = fmt::format("{} after {} iterations",
                                     ceres::TerminationTypeToString(summary.termination_type),
                                     summary.iterations.size() - 1);
  }

  // The phase noise the final stage weights the samples with: the inlier RMS, inflated by how
  // much neighbouring samples share their errors (lens-scale moire, registration, what the
  // field cannot follow). For independent errors the mean of the n residuals in a screen cell
  // has variance sigma^2 / n; the measured n * mean^2 over sigma^2 is the inflation. Without
  // it the covariance would count 100k correlated samples as independent and come out several
  // times too small. The inflation is measured in cells of 1/16, 1/8 and 1/4 of the screen and
  // the largest is kept: the slant is a gradient over the whole height, so errors shared over
  // a quarter of the screen weigh on it most, and on the bench's photos the inflation in 1/4
  // cells is 1.4-3.9 times that in 1/16 cells (docs/calibration.md, "The reported 1-sigma
  // uncertainties"). An error every position shares at the screen's scale leaves no residual
  // and no measure of the residuals can see it.
  void measure_noise(SolverResult& result) {
    double sum2 = 0;
    long n = 0;
    for (size_t i = 0; i < samples_.size(); ++i)
      for (const auto& s : samples_[i]) {
        const double r = residual_of(i, s);
        if (std::abs(r) >= kOutlierBoundPeriods) continue;
        sum2 += r * r;
        ++n;
      }
    if (n < options_.min_noise_samples) {
      obs_sigma_ = options_.obs_sigma;
      result.obs_sigma_periods = obs_sigma_;
      return;
    }
    const double sigma2 = sum2 / double(n);
    double inflation = 1.0;
    for (const int cells : {16, 8, 4}) {
      const double at_scale = inflation_in_cells(cells, sigma2);
      if (at_scale > inflation) {
        inflation = at_scale;
        result.noise_inflation_cells = cells;
      }
    }
    result.noise_inflation = inflation;
    obs_sigma_ = std::max(1e-4, std::sqrt(sigma2 * inflation));
    result.obs_sigma_periods = obs_sigma_;
  }

  // The mean over cells (of 1/cells of the screen per side, per position, with at least
  // options_.min_cell_samples inliers) of n * mean^2 / sigma2: 1 for independent errors, larger
  // when a cell's samples share them.
  double inflation_in_cells(int cells, double sigma2) const {
    double inflation_sum = 0;
    long cells_used = 0;
    std::vector<std::pair<double, long>> sums;
    for (size_t i = 0; i < samples_.size(); ++i) {
      sums.assign(size_t(cells) * cells, {0.0, 0});
      for (const auto& s : samples_[i]) {
        const double r = residual_of(i, s);
        if (std::abs(r) >= kOutlierBoundPeriods) continue;
        const int cu = std::clamp(int(s.u_phys * cells), 0, cells - 1);
        const int cv = std::clamp(int(s.v * cells), 0, cells - 1);
        sums[size_t(cv) * cells + cu].first += r;
        sums[size_t(cv) * cells + cu].second += 1;
      }
      for (const auto& [sum, count] : sums)
        if (count >= options_.min_cell_samples) {
          inflation_sum += sum * sum / double(count);  // = count * mean^2
          ++cells_used;
        }
    }
    return cells_used ? inflation_sum / double(cells_used) / sigma2 : 1.0;
  }

  // Uncertainties: the Gauss-Newton covariance at the solution of the last stage. The samples
  // are weighted by their measured effective noise (measure_noise) and the priors by theirs,
  // so it needs no rescaling.
  void covariance(SolverResult& result) {
    ceres::Covariance::Options co;
    co.algorithm_type = ceres::DENSE_SVD;
    co.null_space_rank = -1;
    co.min_reciprocal_condition_number = options_.min_reciprocal_condition;
    co.num_threads = options_.threads;
    ceres::Covariance cov(co);
    std::vector<const double*> blocks{lens_};
    if (fit_cover_) blocks.push_back(cover_);
    const long field0 = long(blocks.size()) + 3;  // the first control point's row
    for (auto& c : coeffs_) blocks.push_back(&c);
    std::vector<std::pair<const double*, const double*>> pairs;
    for (size_t a = 0; a < blocks.size(); ++a)
      for (size_t b = a; b < blocks.size(); ++b) pairs.emplace_back(blocks[a], blocks[b]);
    if (fit_focal_) pairs.emplace_back(focal_, focal_);
    if (!cov.Compute(pairs, problem_.get())) return;
    const size_t dim = size_t(field0) + coeffs_.size();
    Eigen::MatrixXd c(dim, dim);
    if (!cov.GetCovarianceMatrix(blocks, c.data())) return;
    const char* names[4] = {"pitch_lpi", "slope", "center_periods", "view_cone_deg"};
    for (int i = 0; i < 4; ++i) result.sigma[names[i]] = std::sqrt(std::max(0.0, c(i, i)));
    if (!fit_cone_) result.sigma["view_cone_deg"] = 0;
    double focal_variance = 0;
    if (fit_focal_ && cov.GetCovarianceBlock(focal_, focal_, &focal_variance))
      result.sigma["focal_rel"] = std::sqrt(std::max(0.0, focal_variance));
    if (fit_cover_) result.sigma["cover_thickness_m"] = std::sqrt(std::max(0.0, c(4, 4)));
    if (with_field_) {
      // RMS over the screen of the standard deviation of w.
      double sum = 0;
      const int n = 16;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const display::BSplineWeights wu = display::bspline_weights(nx_, (i + 0.5) / n);
          const display::BSplineWeights wv = display::bspline_weights(ny_, (j + 0.5) / n);
          Eigen::VectorXd g = Eigen::VectorXd::Zero(long(dim));
          for (int b = 0; b < 4; ++b)
            for (int a = 0; a < 4; ++a)
              g[field0 + (wv.i0 + b) * nx_ + wu.i0 + a] = wu.w[a] * wv.w[b];
          sum += g.dot(c * g);
        }
      result.sigma["correction_rms_periods"] = std::sqrt(std::max(0.0, sum / (n * n)));
    }
  }

  // The estimate, the refined cameras and the residual statistics (lens periods).
  void statistics(SolverResult& result) const {
    result.lens = {lens_[0], lens_[1], lens_[2] - std::floor(lens_[2]), lens_[3]};
    if (with_field_) result.correction = display::CorrectionField(nx_, ny_, coeffs_);
    for (size_t i = 0; i < positions_.size(); ++i)
      result.cameras_m.push_back({cams_[3 * i], cams_[3 * i + 1], cams_[3 * i + 2]});
    result.focal_change_rel = focal_[0];
    result.cover.free = fit_cover_;
    result.cover.prior_m = dc_.cover.thickness_m;
    result.cover.prior_sigma_m = fit_cover_ ? options_.cover_sigma_m : 0.0;
    result.cover.thickness_m = dc_.cover.thickness_m + cover_[0];
    // Over all samples with a robust scale (residual_statistics.hpp): pooled, per position on
    // its own scale, and against the other positions pooled (leave one out: against a pool
    // that holds it, a position's ratio could not exceed sqrt(N / N_i)).
    std::vector<std::vector<double>> mine(samples_.size());
    std::vector<double> all;
    for (size_t i = 0; i < samples_.size(); ++i) {
      auto& kept = result.position_samples.emplace_back();
      kept.reserve(samples_[i].size());
      for (const auto& s : samples_[i]) {
        const double r = residual_of(i, s);
        mine[i].push_back(r);
        kept.push_back({float(s.u_phys), float(s.v), float(s.psi), float(r)});
      }
      all.insert(all.end(), mine[i].begin(), mine[i].end());
      result.position_rms.push_back(robust_residuals(mine[i]).stats.rms_periods);
    }
    for (size_t i = 0; i < mine.size() && mine.size() >= 2; ++i) {
      std::vector<double> others;
      for (size_t j = 0; j < mine.size(); ++j)
        if (j != i) others.insert(others.end(), mine[j].begin(), mine[j].end());
      const double rest = robust_residuals(std::move(others)).stats.rms_periods;
      result.position_rms_ratio.push_back(rest > 0 ? result.position_rms[i] / rest : 1.0);
    }
    const RobustResiduals pooled = robust_residuals(std::move(all));
    result.residuals = pooled.stats;
    result.residual_robust_sigma_periods = pooled.robust_sigma_periods;
  }

 private:
  static ceres::Problem::Options problem_options() {
    ceres::Problem::Options po;
    po.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    return po;
  }

  // Samples: subsampled evenly to the cap; their content points (and the field's basis
  // weights there) follow from the start.
  void select_samples() {
    samples_.resize(positions_.size());
    for (size_t i = 0; i < positions_.size(); ++i) {
      const auto& in = positions_[i].samples;
      const size_t cap = size_t(options_.max_samples_per_position);
      const size_t stride = std::max<size_t>(1, (in.size() + cap - 1) / cap);
      for (size_t j = 0; j < in.size(); j += stride) {
        Sample s;
        s.u_phys = in[j].u;
        s.v = in[j].v;
        s.psi = in[j].psi;
        if (!positions_[i].sample_per_cover.empty()) {
          s.du_dt = positions_[i].sample_per_cover.at(j).x();
          s.dv_dt = positions_[i].sample_per_cover.at(j).y();
        }
        if (with_field_) s.wv = display::bspline_weights(ny_, s.v);
        samples_[i].push_back(s);
      }
    }
    update_content_points();
  }

  double* coeff(int ix, int iy) { return &coeffs_[size_t(iy) * nx_ + ix]; }

  // The wrapped residual (lens periods) of sample s of position i at the current estimate.
  double residual_of(size_t i, const Sample& s) const {
    double w = 0;
    if (with_field_)
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a)
          w += coeffs_[size_t(s.wv.i0 + b) * nx_ + size_t(s.wu.i0 + a)] * s.wu.w[a] * s.wv.w[b];
    return wrap_half(s.psi - psi_linear(dc_, lens_, &cams_[3 * i], cover_[0], s, nominal_du_,
                                        nominal_dv_) -
                     dc_.sign * w);
  }

  void add_phase_residuals() {
    const double inv_sigma = 1.0 / obs_sigma_;
    for (size_t i = 0; i < samples_.size(); ++i)
      for (const auto& s : samples_[i]) {
        std::vector<double*> blocks{lens_, &cams_[3 * i], cover_};
        if (with_field_)
          for (int b = 0; b < 4; ++b)
            for (int a = 0; a < 4; ++a) blocks.push_back(coeff(s.wu.i0 + a, s.wv.i0 + b));
        problem_->AddResidualBlock(
            new PhaseResidual(dc_, s, inv_sigma, with_field_, nominal_du_, nominal_dv_),
            loss_.get(), blocks);
      }
  }

  void add_camera_priors() {
    for (size_t i = 0; i < positions_.size(); ++i) {
      const PositionData& p = positions_[i];
      problem_->AddResidualBlock(
          new ceres::AutoDiffCostFunction<CameraPrior, 3, 3, 1, 1>(new CameraPrior{
              p.camera_m.x(), p.camera_m.y(), p.camera_m.z(), p.camera_per_focal_m.x(),
              p.camera_per_focal_m.y(), p.camera_per_focal_m.z(), p.camera_per_cover_m.x(),
              p.camera_per_cover_m.y(), p.camera_per_cover_m.z(), 1.0 / p.lateral_sigma_m,
              1.0 / p.depth_sigma_m}),
          nullptr, &cams_[3 * i], focal_, cover_);
    }
    if (fit_focal_)
      problem_->AddResidualBlock(new ceres::AutoDiffCostFunction<ChangePrior, 1, 1>(
                                     new ChangePrior{1.0 / options_.focal_sigma_rel}),
                                 nullptr, focal_);
    else
      problem_->SetParameterBlockConstant(focal_);
  }

  // The cover's thickness: free under its prior (no thinner than nothing), else held.
  void add_cover_prior() {
    if (!fit_cover_) {
      problem_->SetParameterBlockConstant(cover_);
      return;
    }
    problem_->AddResidualBlock(new ceres::AutoDiffCostFunction<ChangePrior, 1, 1>(
                                   new ChangePrior{1.0 / options_.cover_sigma_m}),
                               nullptr, cover_);
    problem_->SetParameterLowerBound(cover_, 0, -dc_.cover.thickness_m);
  }

  // Second differences of the control points (a prior on the warp's curvature), whitened
  // by the stage's phase noise like the data, so every stage weighs them alike.
  void add_smoothness_prior() {
    const double l = options_.smoothness / obs_sigma_;
    for (int iy = 0; iy < ny_; ++iy)
      for (int ix = 1; ix + 1 < nx_; ++ix)
        problem_->AddResidualBlock(new LinearCombination({l, -2 * l, l}), nullptr,
                                   {coeff(ix - 1, iy), coeff(ix, iy), coeff(ix + 1, iy)});
    for (int iy = 1; iy + 1 < ny_; ++iy)
      for (int ix = 0; ix < nx_; ++ix)
        problem_->AddResidualBlock(new LinearCombination({l, -2 * l, l}), nullptr,
                                   {coeff(ix, iy - 1), coeff(ix, iy), coeff(ix, iy + 1)});
    for (int iy = 0; iy + 1 < ny_; ++iy)
      for (int ix = 0; ix + 1 < nx_; ++ix)
        problem_->AddResidualBlock(
            new LinearCombination({l, -l, -l, l}), nullptr,
            {coeff(ix, iy), coeff(ix + 1, iy), coeff(ix, iy + 1), coeff(ix + 1, iy + 1)});
  }

  // Gauge: the integrals of w times 1, (u - 1/2), (v - 1/2) over the screen are zero, so the
  // field cannot absorb center, pitch or slope.
  void add_gauge_constraints() {
    std::vector<double*> all;
    for (auto& c : coeffs_) all.push_back(&c);
    const double g = 1e4;
    for (int moment = 0; moment < 3; ++moment) {
      std::vector<double> a;
      for (int iy = 0; iy < ny_; ++iy)
        for (int ix = 0; ix < nx_; ++ix) {
          const double mx = moment == 1 ? m1x_[size_t(ix)] * 12 : m0x_[size_t(ix)];
          const double my = moment == 2 ? m1y_[size_t(iy)] * 12 : m0y_[size_t(iy)];
          a.push_back(g * mx * my);
        }
      problem_->AddResidualBlock(new LinearCombination(a), nullptr, all);
    }
  }

  const display::DisplayCalibration& nominal_;
  const DisplayConstants dc_;
  const display::LensModel nominal_lens_;
  const std::vector<PositionData>& positions_;
  const SolverOptions& options_;
  const bool with_field_;
  const int nx_, ny_;
  const bool fit_cone_;
  const bool fit_focal_;  // a self-calibrated camera's focal length (SolverOptions)
  const bool fit_cover_;  // the cover's thickness (SolverOptions::cover_sigma_m)
  const double nominal_du_, nominal_dv_;  // the nominal phase's gradient (periods per u, v)
  double obs_sigma_;
  double focal_[1] = {0};       // relative change of the camera's focal length
  double cover_[1] = {0};       // change of the cover's thickness, metres
  double lens_[4];              // pitch_lpi, slope, center_periods, view_cone_deg
  std::vector<double> cams_;    // Cx, Cy, Cz per position
  std::vector<double> coeffs_;  // nx * ny correction control points
  std::vector<std::vector<Sample>> samples_;
  std::vector<double> m0x_, m1x_, m0y_, m1y_;
  std::unique_ptr<ceres::CauchyLoss> loss_;  // outlives the problem that uses it
  std::unique_ptr<ceres::Problem> problem_;
};

}  // namespace

std::vector<double> camera_shifts_in_sigmas(const std::vector<PositionData>& positions,
                                            const std::vector<Eigen::Vector3d>& refined_m) {
  std::vector<double> out;
  for (size_t i = 0; i < positions.size() && i < refined_m.size(); ++i) {
    const PositionData& p = positions[i];
    const Eigen::Vector3d d = refined_m[i] - p.camera_m;
    out.push_back(Eigen::Vector3d(d.x() / p.lateral_sigma_m, d.y() / p.lateral_sigma_m,
                                  d.z() / p.depth_sigma_m)
                      .norm());
  }
  return out;
}

namespace {

// What the photos alone say of the cover (CoverEstimate): the solve's information on the
// thickness (1 / sigma^2, from the covariance) less the prior's is theirs, and the estimate
// the two combine to splits accordingly (Gaussian: posterior precision and precision-weighted
// mean are sums).
void split_cover_information(CoverEstimate& c) {
  if (!c.free || !(c.sigma_m > 0) || !(c.prior_sigma_m > 0)) return;
  const double posterior = 1 / (c.sigma_m * c.sigma_m);
  const double prior = 1 / (c.prior_sigma_m * c.prior_sigma_m);
  const double photos = posterior - prior;
  if (photos <= 1e-3 * prior) return;  // they say nothing: photos_sigma_m stays infinite
  c.photos_sigma_m = 1 / std::sqrt(photos);
  c.photos_m = (c.thickness_m * posterior - c.prior_m * prior) / photos;
  c.disagreement_sigmas = std::abs(c.photos_m - c.prior_m) /
                          std::hypot(c.photos_sigma_m, c.prior_sigma_m);
}

// The three stages on the options' field grid; with `uncertainties`, sigmas from the
// covariance alone (the refined-grid solve needs only its estimate).
SolverResult solve_on_grid(const display::Calibration& nominal, const LensEstimate& start,
                           const std::vector<PositionData>& positions,
                           const SolverOptions& options, bool uncertainties) {
  LensProblem problem(nominal, start, positions, options);
  SolverResult result;
  // Stage 1: the linear model only, wide loss (the unmodelled warp is up to ~0.3 period).
  problem.solve_stage(options.linear_loss_scale, false, result);
  problem.update_content_points();
  // Stage 2: with the correction field.
  problem.solve_stage(options.field_loss_scale, true, result);
  problem.update_content_points();
  // Stage 3: final robust scale, the measured noise, uncertainties.
  problem.measure_noise(result);
  problem.solve_stage(options.loss_scale, true, result);
  if (uncertainties) problem.covariance(result);
  problem.statistics(result);
  if (const auto it = result.sigma.find("cover_thickness_m"); it != result.sigma.end()) {
    result.cover.sigma_m = it->second;
    split_cover_information(result.cover);
  }
  result.view_cone_fitted = options.fit_view_cone && positions.size() >= 2;
  for (const auto& p : positions) result.position_names.push_back(p.name);
  // Against the registered positions moved with the solve's focal length and cover (the
  // prior's mean).
  std::vector<PositionData> moved;
  const double cover_change = result.cover.thickness_m - result.cover.prior_m;
  for (const auto& p : positions) {
    PositionData& m = moved.emplace_back();  // without the samples
    m.camera_m = p.camera_m + result.focal_change_rel * p.camera_per_focal_m +
                 cover_change * p.camera_per_cover_m;
    m.lateral_sigma_m = p.lateral_sigma_m;
    m.depth_sigma_m = p.depth_sigma_m;
  }
  result.camera_shift_sigmas = camera_shifts_in_sigmas(moved, result.cameras_m);
  return result;
}

// What the field's resolution costs (SolverOptions::field_refinement): the same problem on a
// grid with half the knot spacing, so it holds every field of the solved grid (uniform cubic
// B-splines nest when the segments double), under the same curvature prior per unit of screen:
// the prior's energy sum_nodes (smoothness x second difference)^2 approximates smoothness^2 h^2
// times the integral of the squared second derivatives (h the knot spacing), so halving h
// doubles the weight. What the refined solve moves is what the solved grid could not follow
// of the warp; it leaves no residual, so the covariance cannot see it. Each value's change is
// added to its sigma in quadrature.
void refine_field(const display::Calibration& nominal, const std::vector<PositionData>& positions,
                  const SolverOptions& options, SolverResult& result) {
  const auto t0 = std::chrono::steady_clock::now();
  SolverOptions fine = options;
  fine.grid_nx = 2 * (options.grid_nx - 3) + 3;
  fine.grid_ny = 2 * (options.grid_ny - 3) + 3;
  fine.smoothness = 2 * options.smoothness;
  const SolverResult r = solve_on_grid(nominal, result.lens, positions, fine, false);
  FieldRefinement& out = result.field_refinement;
  out.grid_nx = fine.grid_nx;
  out.grid_ny = fine.grid_ny;
  out.converged = r.converged;
  out.change["pitch_lpi"] = r.lens.pitch_lpi - result.lens.pitch_lpi;
  out.change["slope"] = r.lens.slope - result.lens.slope;
  out.change["center_periods"] = wrap_half(r.lens.center_periods - result.lens.center_periods);
  if (result.view_cone_fitted)
    out.change["view_cone_deg"] = r.lens.view_cone_deg - result.lens.view_cone_deg;
  if (options.focal_sigma_rel > 0)
    out.change["focal_rel"] = r.focal_change_rel - result.focal_change_rel;
  if (result.cover.free)
    out.change["cover_thickness_m"] = r.cover.thickness_m - result.cover.thickness_m;
  // The field's: the screen RMS of the two fields' difference (both in the same gauge).
  double sum = 0;
  const int n = 32;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      const double d = r.correction(u, v) - result.correction(u, v);
      sum += d * d;
    }
  out.change["correction_rms_periods"] = std::sqrt(sum / (n * n));
  for (const auto& [key, change] : out.change) {
    const auto it = result.sigma.find(key);
    if (it != result.sigma.end()) it->second = std::hypot(it->second, change);
  }
  if (result.cover.free) result.cover.sigma_m = result.sigma.at("cover_thickness_m");
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

SolverResult solve_lens(const display::Calibration& nominal, const LensEstimate& start,
                        const std::vector<PositionData>& positions, const SolverOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  SolverResult result = solve_on_grid(nominal, start, positions, options, true);
  if (options.field_refinement && !result.correction.empty() && !result.sigma.empty())
    refine_field(nominal, positions, options, result);
  result.solve_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace lfd::calib
