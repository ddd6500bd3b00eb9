// The cost functions of calib/ whose derivatives are written by hand (calib/solver/
// phase_model.hpp; the others are ceres::AutoDiffCostFunction) against numeric differentiation
// with ceres::GradientChecker, at points a lens solve passes through: the Portrait behind its
// 2 cm block, cameras 0.4-0.9 m away and up to 25 degrees to the side, a start off the truth
// by what the coarse start leaves, a correction field of a few hundredths of a period.
#include "calib/solver/phase_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include <ceres/gradient_checker.h>
#include <gtest/gtest.h>

#include "display/cover_layer.hpp"
#include "display/lens_model.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

using phase_model::DisplayConstants;
using phase_model::LinearCombination;
using phase_model::PhaseResidual;
using phase_model::Sample;

constexpr int kGridNx = 8, kGridNy = 6;  // the field's control points (SolverOptions' grid)
constexpr double kPrecision = 1e-6;      // analytic against central differences, relative

display::DisplayCalibration portrait_behind_its_block() {
  display::DisplayCalibration d =
      display::read_visual_json(test::fixture_calibration("LKG-PORT-portrait.visual.json"));
  d.cover = display::cover_layer_for_family(d).cover;
  return d;
}

// The unknowns of one phase residual at one point of a solve.
struct SolvePoint {
  std::array<double, 4> lens;  // pitch_lpi, slope, center_periods, view_cone_deg
  std::array<double, 3> camera_m;
  double cover_change_m;
  std::array<double, 16> field;  // the 4x4 control points over the sample, b-major
};

// The parameter blocks in PhaseResidual's order.
std::vector<const double*> blocks_of(const SolvePoint& p, bool with_field) {
  std::vector<const double*> blocks{p.lens.data(), p.camera_m.data(), &p.cover_change_m};
  if (with_field)
    for (const double& c : p.field) blocks.push_back(&c);
  return blocks;
}

// A sample at physical point (u_phys, v) for the point's camera, its content point and the
// nominal phase there as update_content_points puts them, `psi` the model's phase at `truth`
// plus `offset` periods (a residual well inside (-0.5, 0.5), away from the wrap).
Sample sample_at(const display::DisplayCalibration& nominal, const DisplayConstants& dc,
                 const SolvePoint& truth, double u_phys, double v, double offset, double& nominal_du,
                 double& nominal_dv) {
  const auto nominal_terms = display::shader_terms(dc.geometry, nominal.pitch_lpi, nominal.slope);
  nominal_du = nominal_terms.pitch_periods;
  nominal_dv = nominal_du * nominal_terms.tilt;
  Sample s;
  s.u_phys = u_phys;
  s.v = v;
  // Registration through a thicker cover moves the panel point (PositionData::sample_per_cover):
  // of the order of the cover's apparent shift per metre of thickness, over the screen's size.
  s.du_dt = 0.8;
  s.dv_dt = -0.3;
  const auto terms = display::shader_terms(dc.geometry, truth.lens[0], truth.lens[1]);
  const double dt = truth.cover_change_m;
  const double f_seen = dc.seen(truth.camera_m.data(), s.u_phys + dt * s.du_dt, s.v + dt * s.dv_dt,
                                terms.tilt, truth.lens[3], dt);
  s.u = s.u_phys + display::lens_content_shift(f_seen, nominal.inv_view) / terms.pitch_periods;
  s.a_nom = display::LensModel(nominal).phase({s.u, s.v});
  s.wu = display::bspline_weights(kGridNx, s.u);
  s.wv = display::bspline_weights(kGridNy, s.v);
  double w = 0;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) w += truth.field[size_t(4 * b + a)] * s.wu.w[a] * s.wv.w[b];
  s.psi = phase_model::psi_linear(dc, truth.lens.data(), truth.camera_m.data(), dt, s, nominal_du,
                                  nominal_dv) +
          dc.sign * w + offset;
  s.psi -= std::floor(s.psi);  // decoded phases are known modulo 1
  return s;
}

SolvePoint solve_point(const display::DisplayCalibration& d, std::array<double, 3> camera_m,
                       double cover_change_m, double field_scale) {
  SolvePoint p;
  p.lens = {d.pitch_lpi * (1 + 1e-4), d.slope * (1 - 2e-4), 0.37, d.view_cone_deg - 1.5};
  p.camera_m = camera_m;
  p.cover_change_m = cover_change_m;
  for (size_t i = 0; i < p.field.size(); ++i)
    p.field[i] = field_scale * std::sin(1.7 * double(i) + 0.3);
  return p;
}

// The checker differentiates with Ridders' method, whose first step is a fraction of the
// parameter block's norm: 1 % by default, 0.65 lpi on the lens block, which moves the phase by
// periods and wraps the residual (a phase is known modulo 1). 1e-5 moves it by a thousandth.
ceres::NumericDiffOptions steps_within_a_period() {
  ceres::NumericDiffOptions o;
  o.ridders_relative_initial_step_size = 1e-5;
  return o;
}

void expect_gradients_match(const ceres::CostFunction& cost, const std::vector<const double*>& blocks,
                            const ceres::NumericDiffOptions& numeric = {}) {
  const std::vector<const ceres::Manifold*>* no_manifolds = nullptr;
  const ceres::GradientChecker checker(&cost, no_manifolds, numeric);
  ceres::GradientChecker::ProbeResults results;
  EXPECT_TRUE(checker.Probe(blocks.data(), kPrecision, &results)) << results.error_log;
  EXPECT_TRUE(results.return_value);
  // The check compared something: the analytic Jacobian is not all zeros.
  double largest = 0;
  for (const auto& j : results.jacobians) largest = std::max(largest, j.cwiseAbs().maxCoeff());
  EXPECT_GT(largest, 0);
}

TEST(CostGradients, PhaseResidualMatchesNumericDifferentiation) {
  const display::DisplayCalibration nominal = portrait_behind_its_block();
  for (const bool vertical_parallax : {true, false}) {
    const DisplayConstants dc = DisplayConstants::of(nominal, vertical_parallax);
    // Head-on and near, to the side and far, above and to the other side with a thinner cover.
    const SolvePoint points[] = {solve_point(nominal, {0.0, 0.0, 0.45}, 0.0, 0.02),
                                 solve_point(nominal, {0.25, -0.03, 0.62}, 0.0015, 0.04),
                                 solve_point(nominal, {-0.3, 0.12, 0.9}, -0.004, 0.01)};
    const std::array<double, 2> where[] = {{0.5, 0.5}, {0.13, 0.81}, {0.92, 0.07}};
    for (const SolvePoint& truth : points)
      for (const auto& [u, v] : where)
        for (const bool with_field : {true, false}) {
          SCOPED_TRACE(::testing::Message() << "camera (" << truth.camera_m[0] << ", "
                                            << truth.camera_m[1] << ", " << truth.camera_m[2]
                                            << ") at (" << u << ", " << v << ")"
                                            << (with_field ? " with the field" : "")
                                            << (vertical_parallax ? "" : ", horizontal only"));
          double du = 0, dv = 0;
          const Sample s = sample_at(nominal, dc, truth, u, v, 0.06, du, dv);
          const PhaseResidual cost(dc, s, 1.0 / 0.01, with_field, du, dv);
          // At the unknowns the sample was made from, the residual is the offset, whitened
          // (without the field, the field's part of the sample too).
          double r = 0;
          const std::vector<const double*> at_truth = blocks_of(truth, with_field);
          ASSERT_TRUE(cost.Evaluate(at_truth.data(), &r, nullptr));
          double field = 0;
          for (int b = 0; b < 4; ++b)
            for (int a = 0; a < 4; ++a) field += truth.field[size_t(4 * b + a)] * s.wu.w[a] * s.wv.w[b];
          const double expected = with_field ? 0.06 : 0.06 + dc.sign * field;
          EXPECT_NEAR(r, expected / 0.01, 1e-6);
          // Away from them, where a solve's iterations pass: the Jacobian is the derivative.
          SolvePoint moved = truth;
          moved.lens[0] *= 1 + 3e-5;
          moved.lens[2] += 0.01;
          moved.lens[3] += 0.4;
          moved.camera_m[0] += 0.002;
          moved.camera_m[2] -= 0.004;
          moved.cover_change_m += 0.0005;
          moved.field[5] += 0.01;
          expect_gradients_match(cost, blocks_of(truth, with_field), steps_within_a_period());
          expect_gradients_match(cost, blocks_of(moved, with_field), steps_within_a_period());
        }
  }
}

TEST(CostGradients, LinearCombinationMatchesNumericDifferentiation) {
  // The solve's own coefficients: a second difference whitened by the phase noise (smoothness
  // 1e-3 over 0.01 period), the mixed difference, and a gauge row over the whole 8x6 grid.
  const double l = 1e-3 / 0.01;
  std::vector<double> gauge;
  for (int i = 0; i < kGridNx * kGridNy; ++i) gauge.push_back(1e4 * (0.01 + 0.002 * (i % 7)));
  for (const std::vector<double>& a :
       {std::vector<double>{l, -2 * l, l}, std::vector<double>{l, -l, -l, l}, gauge}) {
    const LinearCombination cost(a);
    std::vector<double> x(a.size());
    for (size_t i = 0; i < x.size(); ++i) x[i] = 0.03 * std::cos(0.9 * double(i));
    std::vector<const double*> blocks;
    for (const double& xi : x) blocks.push_back(&xi);
    expect_gradients_match(cost, blocks);
    // Its value is the combination it was given.
    double r = 0, expected = 0;
    ASSERT_TRUE(cost.Evaluate(blocks.data(), &r, nullptr));
    for (size_t i = 0; i < x.size(); ++i) expected += a[i] * x[i];
    EXPECT_NEAR(r, expected, 1e-12 * std::abs(expected) + 1e-15);
  }
}

}  // namespace
}  // namespace lfd::calib
