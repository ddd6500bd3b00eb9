// The display half of the forward model (docs/validation.md "The forward model"), through
// DisplaySimulator::radiance.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "display/lens_optics.hpp"
#include "sim/simulator.hpp"
#include "simulator_test_support.hpp"
#include "util/error.hpp"

namespace lfd::sim {
namespace {

using testing::apw92011;
using testing::view_index_panel;

// An eye 0.6 m from panel point p, in the direction that shows view fraction f.
Eigen::Vector3d eye_for_fraction(const display::DisplayCalibration& c, const Eigen::Vector3d& p, double f) {
  const double tan_theta = (f - 0.5) * 2.0 * std::tan(0.5 * c.view_cone_deg * std::numbers::pi / 180.0);
  return p + Eigen::Vector3d(0.6 * tan_theta, 0.0, 0.6);
}

std::vector<Eigen::Vector3d> random_panel_points(const display::DisplayCalibration& c, int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(-0.45, 0.45);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) points.emplace_back(ux(rng) * c.width_m(), ux(rng) * c.height_m(), 0);
  return points;
}

TEST(SimulatorOptics, UniformWhitePanelAveragesToOne) {
  const DisplaySimulator sim{display::LensModel(apw92011())};
  const auto& c = sim.lens().calibration();
  const ImageF white(c.screen_w, c.screen_h, 3, 1.0f);
  std::array<double, 3> sum{};
  const auto points = random_panel_points(c, 4000, 7);
  for (const auto& p : points) {
    const auto r = sim.radiance(white, p, eye_for_fraction(c, p, 0.37), 0.008);
    for (int ch = 0; ch < 3; ++ch) sum[ch] += r[ch];
  }
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(sum[ch] / points.size(), 1.0, 0.05) << "channel " << ch;
}

TEST(SimulatorOptics, BlackPanelEmitsNothing) {
  const DisplaySimulator sim{display::LensModel(apw92011())};
  const auto& c = sim.lens().calibration();
  const ImageF black(c.screen_w, c.screen_h, 3, 0.0f);
  const auto r = sim.radiance(black, {0.01, 0.02, 0}, {0.1, 0, 0.6}, 0.008);
  EXPECT_EQ(r[0] + r[1] + r[2], 0.0f);
}

// The defining property of a calibrated display: an eye in view j's direction sees view j.
void expect_eye_sees_its_view(const display::DisplayCalibration& display) {
  const int views = 24;
  const DisplaySimulator sim{display::LensModel(display)};
  const auto& c = sim.lens().calibration();
  const ImageF index = view_index_panel(sim.lens(), views);
  const ImageF white(c.screen_w, c.screen_h, 3, 1.0f);
  const auto points = random_panel_points(c, 600, 3);
  for (int j : {2, 11, 20}) {
    int near = 0, total = 0;
    double mean_view = 0;
    for (const auto& p : points) {
      const Eigen::Vector3d eye = eye_for_fraction(c, p, (j + 0.5) / views);
      const auto ri = sim.radiance(index, p, eye, 0.008);
      const auto rw = sim.radiance(white, p, eye, 0.008);
      for (int ch = 0; ch < 3; ++ch) {
        if (rw[ch] < 0.5f) continue;  // the point sees a gap between channel-ch subpixels
        const double seen = ri[ch] / rw[ch] * (views - 1);
        mean_view += seen;
        near += std::abs(seen - j) <= 1.0;
        ++total;
      }
    }
    ASSERT_GT(total, 300);
    EXPECT_NEAR(mean_view / total, j, 0.3) << "view " << j;
    EXPECT_GT(double(near) / total, 0.85) << "view " << j;
  }
}

TEST(SimulatorOptics, EyeInViewDirectionSeesThatView) { expect_eye_sees_its_view(apw92011()); }

TEST(SimulatorOptics, EyeInViewDirectionSeesThatViewOnGen3Cells) {
  expect_eye_sees_its_view(testing::small_gen3_portrait());
}

TEST(SimulatorOptics, Gen3WhitePanelAveragesToOne) {
  const DisplaySimulator sim{display::LensModel(testing::small_gen3_portrait())};
  const auto& c = sim.lens().calibration();
  const ImageF white(c.screen_w, c.screen_h, 3, 1.0f);
  std::array<double, 3> sum{};
  const auto points = random_panel_points(c, 4000, 11);
  for (const auto& p : points) {
    const auto r = sim.radiance(white, p, eye_for_fraction(c, p, 0.61), 0.008);
    for (int ch = 0; ch < 3; ++ch) sum[ch] += r[ch];
  }
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(sum[ch] / points.size(), 1.0, 0.05) << "channel " << ch;
}

TEST(SimulatorOptics, ViewsRepeatOutsideTheCone) {
  const DisplaySimulator sim{display::LensModel(apw92011())};
  const auto& c = sim.lens().calibration();
  const ImageF index = view_index_panel(sim.lens(), 24);
  const Eigen::Vector3d p(0.02, -0.01, 0);
  // Fraction 0.3 and 1.3 leave through neighbouring lenses but show the same view.
  const auto a = sim.radiance(index, p, eye_for_fraction(c, p, 0.3), 0.008);
  const auto b = sim.radiance(index, p, eye_for_fraction(c, p, 1.3), 0.008);
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(a[ch], b[ch], 1e-4);
}

// With a correction field the seen point is found by Newton steps; it must land on the
// phase that shows the seen fraction, within the lens covering P.
TEST(SimulatorOptics, SeenPointHasTheSeenPhaseWithACorrectionField) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coefficient(-0.4, 0.4), unit(0.02, 0.98);
  std::vector<double> w(8 * 6);
  for (double& x : w) x = coefficient(rng);
  const display::LensModel lens(apw92011(), display::CorrectionField(8, 6, w));
  const ImageF panel(3840, 2160, 1, 0.0f);
  const display::PhaseKernel kernel = display::LensOptics::make_kernel(lens, 0.008);
  const display::LensOptics optics(lens, panel, kernel);
  for (int i = 0; i < 2000; ++i) {
    const double u = unit(rng), v = unit(rng), f = unit(rng);
    const double u_q = optics.seen_u(u, v, f);
    const double target = lens.phase_for_fraction(f, std::floor(lens.phase(u, v)));
    ASSERT_NEAR(lens.phase(u_q, v), target, 1e-9) << "u " << u << " v " << v << " f " << f;
    ASSERT_NEAR(lens.view_fraction(lens.phase(u_q, v)), f, 1e-6);
  }
}

TEST(SimulatorOptics, WrongPanelSizeIsInputError) {
  const DisplaySimulator sim{display::LensModel(apw92011())};
  const ImageF wrong(1920, 1080, 3, 1.0f);
  EXPECT_THROW(sim.radiance(wrong, {0, 0, 0}, {0, 0, 0.6}, 0.008), InputError);
  const PhysicalCamera cam(CameraIntrinsics::from_fov(40, 64, 36), CameraPose{});
  EXPECT_THROW(sim.capture(wrong, cam, CaptureEffects{}), InputError);
}

}  // namespace
}  // namespace lfd::sim
