// The lens solver through a cover layer (docs/calibration.md, "The cover layer"): phase samples of
// a 16" Gen2 behind a 2 cm acrylic block, seen by cameras 25 degrees to either side, where the
// exact refracted ray differs from the paraxial one by up to 0.005 period. Solved with the block,
// the truth and the cameras come back within the bars. Solved as a bare panel (its registration
// puts each camera the apparent t (1 - 1/n) nearer, as RegistrationThroughCover measures), the
// cameras stay at the apparent distance, which absorbs the paraxial block: on exact phase samples
// the rest (the tan^2 part) is absorbed by the lens and the correction field too (measured here:
// center 0.0032, cone 0.01 deg). What ignoring the block costs end to end comes from mapping photo
// pixels to panel points (docs/calibration.md, "The cover layer"). Below (docs/calibration.md, "An
// unknown cover"): the block's thickness unknown, free under a prior.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "display/visual_json.hpp"
#include "calib/solver/lens_solver.hpp"
#include "calib/solver/quality_gates.hpp"
#include "tests/calib/synthetic_phase_samples.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

struct Misses {
  double slant_deg, pitch_rel, center, cone_deg;
};

Misses misses(const SolverResult& r, const display::Calibration& truth) {
  const display::DisplayCalibration& t = truth.display;
  const double dc = r.lens.center_periods - t.center_periods;
  return {std::abs(display::slant_deg_of_slope(r.lens.slope) - display::slant_deg_of_slope(t.slope)),
          std::abs(r.lens.pitch_lpi / t.pitch_lpi - 1), std::abs(dc - std::round(dc)),
          std::abs(r.lens.view_cone_deg - t.view_cone_deg)};
}

// A start as near as the coarse start leaves it.
LensEstimate start_near(const display::Calibration& truth) {
  LensEstimate start;
  start.pitch_lpi = truth.display.pitch_lpi * (1 + 1e-4);
  start.slope = display::slope_of_slant_deg(display::slant_deg_of_slope(truth.display.slope) + 0.01);
  start.center_periods = truth.display.center_periods + 0.04;
  start.view_cone_deg = truth.display.view_cone_deg - 1.5;
  return start;
}

TEST(LensSolverThroughCover, MeetsTheBarsAndFindsTheCamerasBehindTheBlock) {
  display::DisplayCalibration real = display::read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json"));
  real.cover = {0.02, 1.49};
  sim::SyntheticUnitOptions unit;
  unit.warp_amplitude = 0.1;
  testing::SyntheticPhaseOptions o;
  o.noise_periods = 0.005;
  const std::vector<Eigen::Vector3d> cameras{
      {0.23, 0.02, 0.5}, {-0.26, -0.03, 0.56}, {0.02, 0.03, 0.66}};
  const testing::SyntheticPhaseData data = testing::make_synthetic_phase_data(real, unit, cameras, o);
  const display::Calibration& truth = data.unit.truth;
  const LensEstimate start = start_near(truth);
  SolverOptions grid;
  grid.grid_nx = grid.grid_ny = 6;

  const SolverResult with = solve_lens(data.unit.nominal, start, data.positions, grid);
  ASSERT_TRUE(with.converged) << with.report;
  const Misses m = misses(with, truth);
  std::printf("with the block: slant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg\n",
              m.slant_deg, m.pitch_rel, m.center, m.cone_deg);
  EXPECT_LT(m.slant_deg, 0.001);
  EXPECT_LT(m.pitch_rel, 2e-5);
  EXPECT_LT(m.center, 0.005);
  EXPECT_LT(m.cone_deg, 0.5);
  ASSERT_EQ(with.cameras_m.size(), cameras.size());
  for (size_t i = 0; i < cameras.size(); ++i)
    EXPECT_NEAR(with.cameras_m[i].z(), cameras[i].z(), 0.002) << "camera " << i;

  display::Calibration bare = data.unit.nominal;
  bare.display.cover = {};
  std::vector<PositionData> apparent = data.positions;
  for (auto& p : apparent) p.camera_m.z() -= real.cover.apparent_shift_m();
  const SolverResult without = solve_lens(bare, start, apparent, grid);
  const Misses w = misses(without, truth);
  std::printf("as a bare panel: slant %.5f deg, pitch %.2e, center %.4f, cone %.3f deg\n",
              w.slant_deg, w.pitch_rel, w.center, w.cone_deg);
  ASSERT_EQ(without.cameras_m.size(), cameras.size());
  for (size_t i = 0; i < cameras.size(); ++i)
    EXPECT_NEAR(without.cameras_m[i].z(), cameras[i].z() - real.cover.apparent_shift_m(), 0.002)
        << "camera " << i;
}

}  // namespace
}  // namespace lfd::calib

namespace lfd::calib {
namespace {

// The same block of unknown thickness (docs/calibration.md, "An unknown cover"): phase samples of a
// 16" Gen2 behind 2 cm of acrylic, the solve told only "0-25 mm" (a uniform prior: 12.5 +- 7.2 mm).
// Registration through the assumed 12.5 mm puts each camera the paraxial difference nearer than it
// is (RegistrationThroughCover) and moves it back as the thickness grows (camera_per_cover_m).
struct CoverCase {
  SolverResult solve;
  Misses held;     // the same samples solved with the thickness held at the prior's mean
  Misses free;
};

CoverCase solve_unknown_block(const std::vector<Eigen::Vector3d>& cameras, double prior_m,
                              double prior_sigma_m) {
  display::DisplayCalibration real =
      display::read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json"));
  real.cover = {0.02, 1.49};
  sim::SyntheticUnitOptions unit;
  unit.warp_amplitude = 0.1;
  testing::SyntheticPhaseOptions o;
  o.noise_periods = 0.005;
  const testing::SyntheticPhaseData data = testing::make_synthetic_phase_data(real, unit, cameras, o);
  const display::Calibration& truth = data.unit.truth;
  display::Calibration assumed = data.unit.nominal;
  assumed.display.cover.thickness_m = prior_m;
  const double per_metre = 1 - 1 / real.cover.refractive_index;  // apparent shift per metre
  std::vector<PositionData> registered = data.positions;
  for (auto& p : registered) {
    p.camera_m.z() += (prior_m - real.cover.thickness_m) * per_metre;
    p.camera_per_cover_m = {0, 0, per_metre};
  }
  const LensEstimate start = start_near(truth);
  SolverOptions options;
  options.grid_nx = options.grid_ny = 6;
  options.field_refinement = false;
  CoverCase out;
  out.held = misses(solve_lens(assumed, start, registered, options), truth);
  options.cover_sigma_m = prior_sigma_m;
  out.solve = solve_lens(assumed, start, registered, options);
  out.free = misses(out.solve, truth);
  const CoverEstimate& c = out.solve.cover;
  std::printf("held at %.1f mm: cone error %.3f deg, center %.4f; free: %.2f +- %.2f mm (photos "
              "alone %.2f +- %.2f, %.1f sigmas from the prior), cone error %.3f +- %.3f deg, "
              "center %.4f +- %.4f\n",
              1e3 * prior_m, out.held.cone_deg, out.held.center, 1e3 * c.thickness_m,
              1e3 * c.sigma_m, 1e3 * c.photos_m, 1e3 * c.photos_sigma_m, c.disagreement_sigmas,
              out.free.cone_deg, out.solve.sigma.at("view_cone_deg"), out.free.center,
              out.solve.sigma.at("center_periods"));
  return out;
}

// Cameras 25 degrees to either side see the tan^2 part of the refraction: the thickness is
// measured, and its truth lies within 3 of its sigmas.
TEST(LensSolverThroughCover, AnUnknownBlockIsMeasuredFromCamerasFarOffAxis) {
  const CoverCase c = solve_unknown_block({{0.23, 0.02, 0.5}, {-0.26, -0.03, 0.56}, {0.02, 0.03, 0.66}},
                                          0.0125, 0.025 / std::sqrt(12.0));
  ASSERT_TRUE(c.solve.converged) << c.solve.report;
  const CoverEstimate& cover = c.solve.cover;
  ASSERT_TRUE(cover.free);
  EXPECT_TRUE(cover.measured()) << "sigma " << cover.sigma_m << " of a prior " << cover.prior_sigma_m;
  EXPECT_LT(std::abs(cover.thickness_m - 0.02), 3 * cover.sigma_m);
  EXPECT_LT(cover.disagreement_sigmas, 3.0);
  EXPECT_LT(c.free.cone_deg, 2 * c.solve.sigma.at("view_cone_deg"));
}

// Cameras near the axis cannot tell the thickness: it stays near the prior's mean, and the
// prior's spread goes into the sigmas, which then cover what assuming the mean costs.
TEST(LensSolverThroughCover, AnUnknownBlockSeenNearTheAxisWidensTheSigmas) {
  const CoverCase c = solve_unknown_block({{0.05, 0.02, 0.5}, {-0.04, -0.03, 0.62}, {0.02, 0.03, 0.75}},
                                          0.0125, 0.025 / std::sqrt(12.0));
  ASSERT_TRUE(c.solve.converged) << c.solve.report;
  const CoverEstimate& cover = c.solve.cover;
  EXPECT_FALSE(cover.measured());
  EXPECT_LT(c.free.cone_deg, 2 * c.solve.sigma.at("view_cone_deg"));
  EXPECT_LT(c.free.center, 2 * c.solve.sigma.at("center_periods"));
  EXPECT_LT(c.free.pitch_rel * c.solve.lens.pitch_lpi, 2 * c.solve.sigma.at("pitch_lpi"));
}

// A bare panel given (0 +- 1 mm) where the photos, from far off axis, see a 2 cm block: the
// gate names the cover.
TEST(LensSolverThroughCover, PhotosThatContradictTheCoverGivenAreRefused) {
  const CoverCase c = solve_unknown_block({{0.23, 0.02, 0.5}, {-0.26, -0.03, 0.56}, {0.02, 0.03, 0.66}},
                                          0.0, 0.001);
  EXPECT_GT(c.solve.cover.disagreement_sigmas, 3.0);
  display::Calibration solved;
  solved.display.pitch_lpi = c.solve.lens.pitch_lpi;
  const std::vector<std::string> fails = QualityGates{}.evaluate(solved, c.solve);
  bool named = false;
  for (const auto& f : fails) named = named || f.find("contradict the cover given") != std::string::npos;
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace lfd::calib
