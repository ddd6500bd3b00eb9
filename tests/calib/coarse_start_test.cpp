// The coarse start (calib/solver/coarse_start.hpp): from a nominal model 1 % off in pitch and 0.5 deg
// in slant, whose phase wraps many times across the screen, the planes of the decoded phase
// give a start from which the local solver reaches the truth.
#include "calib/solver/coarse_start.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "tests/calib/synthetic_phase_samples.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

using calib::testing::make_synthetic_phase_data;
using calib::testing::SyntheticPhaseData;
using calib::testing::three_cameras;

double wrapped(double x) { return x - std::round(x); }

// The largest wrapped difference, over the screen and the cameras, between the phase the
// solver's linear model predicts with `lens` and with the truth (the warp left out): the
// solver's first stage locks onto the right wrap only where it is well under half a period.
double worst_phase_error(const SyntheticPhaseData& data, const LensEstimate& lens) {
  const display::DisplayCalibration& t = data.unit.truth.display;
  const display::DisplayCalibration& nom = data.unit.nominal.display;
  const double s = t.inv_view ? 1.0 : -1.0;
  auto linear_psi = [&](double pitch, double slope, double center, double cone,
                        const Eigen::Vector3d& c, double u, double v) {
    const display::ShaderTerms<double> terms = display::shader_terms(t.geometry(), pitch, slope);
    const display::ShaderTerms<double> nominal = display::shader_terms(nom.geometry(), nom.pitch_lpi, nom.slope);
    const double a = (u + v * terms.tilt) * terms.pitch_periods - center;
    const double a_nom = (u + v * nominal.tilt) * nominal.pitch_periods - nom.center_periods;
    return display::seen_fraction(c.x() - (u - 0.5) * t.width_m(), c.y() - (v - 0.5) * t.height_m(), c.z(),
                         display::line_tilt(t.geometry(), terms.tilt), cone) +
           s * (a - a_nom);
  };
  double worst = 0;
  for (const auto& c : data.cameras)
    for (int j = 0; j <= 20; ++j)
      for (int i = 0; i <= 20; ++i) {
        const double u = i / 20.0, v = j / 20.0;
        const double est = linear_psi(lens.pitch_lpi, lens.slope, lens.center_periods,
                                      lens.view_cone_deg, c, u, v);
        const double tru = linear_psi(t.pitch_lpi, t.slope, t.center_periods, t.view_cone_deg, c, u, v);
        worst = std::max(worst, std::abs(wrapped(est - tru)));
      }
  return worst;
}

LensEstimate nominal_lens(const display::Calibration& nominal) {
  return {nominal.display.pitch_lpi, nominal.display.slope, nominal.display.center_periods,
          nominal.display.view_cone_deg};
}

class CoarseStart : public ::testing::TestWithParam<const char*> {};

TEST_P(CoarseStart, LandsWithinTheSolversReachOfTheTruth) {
  const display::DisplayCalibration real = display::read_visual_json(test::fixture_calibration(GetParam()));
  const SyntheticPhaseData data = make_synthetic_phase_data(real, {}, three_cameras(real));
  const display::DisplayCalibration& t = data.unit.truth.display;
  std::vector<PhasePlane> planes;
  const LensEstimate e = coarse_start(data.unit.nominal, data.positions, true, &planes);
  const double start_error = worst_phase_error(data, e);
  std::printf("%s: pitch %.2e rel, slant %.4f deg, center %.4f, cone %.2f deg; worst phase %.3f "
              "(nominal %.3f)\n",
              GetParam(), e.pitch_lpi / t.pitch_lpi - 1,
              display::slant_deg_of_slope(e.slope) - display::slant_deg_of_slope(t.slope),
              wrapped(e.center_periods - t.center_periods), e.view_cone_deg - t.view_cone_deg,
              start_error, worst_phase_error(data, nominal_lens(data.unit.nominal)));

  // The nominal model is hopeless for a local solver: its phase is off by whole periods.
  EXPECT_GT(worst_phase_error(data, nominal_lens(data.unit.nominal)), 0.45);
  // The start is within a fraction of a period everywhere.
  EXPECT_LT(start_error, 0.2);
  EXPECT_LT(std::abs(e.pitch_lpi / t.pitch_lpi - 1), 5e-4);  // from 1 %
  EXPECT_LT(std::abs(display::slant_deg_of_slope(e.slope) - display::slant_deg_of_slope(t.slope)), 0.02);  // from 0.5
  EXPECT_LT(std::abs(wrapped(e.center_periods - t.center_periods)), 0.1);
  // The cone enters the phase weakly (it scales the seen fraction, 0.5 +- 0.2 here), so the
  // planes measure it coarsely: a few degrees off costs a few hundredths of a period.
  EXPECT_LT(std::abs(e.view_cone_deg - t.view_cone_deg), 5.0);
  // Every position's phase is a clean plane (the warp is small against the moire).
  ASSERT_EQ(planes.size(), 3u);
  for (const auto& p : planes) EXPECT_GT(p.coherence, 0.5);

  // And the solver, started there, lands where it lands from the truth: the start is in the
  // right basin. What is left is the data's own error (the registration priors here are 1 mm
  // and 3 mm, which leave the Portrait's cone at a sigma of 1.2 degrees), covered by the sigmas.
  SolverOptions options;
  options.grid_nx = options.grid_ny = 6;
  const SolverResult r = solve_lens(data.unit.nominal, e, data.positions, options);
  const LensEstimate truth{t.pitch_lpi, t.slope, t.center_periods, t.view_cone_deg};
  const SolverResult from_truth = solve_lens(data.unit.nominal, truth, data.positions, options);
  EXPECT_NEAR(r.lens.pitch_lpi / from_truth.lens.pitch_lpi - 1, 0.0, 1e-6);
  EXPECT_NEAR(wrapped(r.lens.center_periods - from_truth.lens.center_periods), 0.0, 1e-3);
  EXPECT_NEAR(r.lens.view_cone_deg, from_truth.lens.view_cone_deg, 0.02);
  EXPECT_LT(std::abs(r.lens.pitch_lpi - t.pitch_lpi), 3 * r.sigma.at("pitch_lpi"));
  EXPECT_LT(std::abs(wrapped(r.lens.center_periods - t.center_periods)), 3 * r.sigma.at("center_periods"));
  EXPECT_LT(std::abs(r.lens.view_cone_deg - t.view_cone_deg), 3 * r.sigma.at("view_cone_deg"));
}

INSTANTIATE_TEST_SUITE_P(RealUnits, CoarseStart,
                         ::testing::Values("LKG-APW92011.visual.json", "LKG-PORT-portrait.visual.json",
                                           "LKG-2K-04409.visual.json"),
                         [](const auto& info) {
                           std::string name = info.param;
                           name = name.substr(0, name.find('.'));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(FitPhasePlane, FindsTheFrequencyAndPhaseOfAWrappedPlane) {
  std::vector<PhaseSample> samples;
  const double alpha = 0.3, bu = 6.7, bv = -3.2;
  for (int j = 0; j < 60; ++j)
    for (int i = 0; i < 100; ++i) {
      const double u = (i + 0.5) / 100, v = (j + 0.5) / 60;
      double psi = alpha + bu * u + bv * v;
      psi -= std::floor(psi);
      samples.push_back({float(u), float(v), float(psi), 1.0f});
    }
  const PhasePlane p = fit_phase_plane(samples);
  EXPECT_NEAR(p.beta_u, bu, 0.01);
  EXPECT_NEAR(p.beta_v, bv, 0.01);
  EXPECT_NEAR(wrapped(p.alpha - alpha), 0.0, 0.01);
  EXPECT_GT(p.coherence, 0.99);
}

TEST(FitPhasePlane, RandomPhaseHasNoCoherence) {
  std::vector<PhaseSample> samples;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (int i = 0; i < 4000; ++i) samples.push_back({uni(rng), uni(rng), uni(rng), 1.0f});
  EXPECT_LT(fit_phase_plane(samples).coherence, 0.2);
}

}  // namespace
}  // namespace lfd::calib
