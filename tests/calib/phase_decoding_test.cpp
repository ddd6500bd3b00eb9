// Phase decoding (calib/decoding/phase_decoding.hpp) on synthetic K-step images: a camera whose pose is
// known looks at a panel that shows I_k = a + b cos(2 pi (psi(u, v) - k/K)) for a known psi;
// the decoded samples must give back psi where the camera looks, and say what they left out.
#include "calib/decoding/phase_decoding.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "sim/camera_model.hpp"
#include "display/visual_json.hpp"
#include "tests/test_data.hpp"

namespace lfd::calib {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double wrapped(double x) { return x - std::round(x); }

// The phase the panel shows: a plane with a few fringes plus a smooth bend.
double true_psi(double u, double v) {
  return 0.21 + 3.4 * u - 1.7 * v + 0.08 * std::sin(kTwoPi * 1.3 * u) * std::cos(kTwoPi * v);
}

struct Scene {
  sim::PatternSet set;
  sim::PhysicalCamera camera;
  Registration registration;
};

// The board corners as the camera sees them (exact projections) register the panel.
Registration register_by_projection(const sim::PatternSet& set, const sim::PhysicalCamera& camera) {
  BoardDetection board;
  board.image_size = {camera.intrinsics().width, camera.intrinsics().height};
  for (size_t id = 0; id < set.board.corners_px.size(); ++id) {
    const display::ScreenUV uv = panel_px_to_uv(set.nominal.display, set.board.corners_px[id]);
    Eigen::Vector2d px;
    if (!camera.project(uv_to_display_m(set.nominal.display, uv), px)) continue;
    board.ids.push_back(int(id));
    board.image_px.emplace_back(float(px.x()), float(px.y()));
  }
  return Registration(board, set, camera.intrinsics());
}

Scene make_scene() {
  display::Calibration nominal;
  nominal.display = display::read_visual_json(test::fixture_calibration("LKG-APW92011.visual.json"));
  sim::PatternSet set = sim::plan_patterns(nominal);
  sim::CameraPose pose;
  pose.position_m = {0.03, 0.01, 0.5};
  pose.look_at_m = {0.0, 0.0, 0.0};
  sim::PhysicalCamera camera(sim::CameraIntrinsics::from_fov(50.0, 320, 240), pose);
  Registration registration = register_by_projection(set, camera);
  return {std::move(set), std::move(camera), std::move(registration)};
}

struct CaptureOptions {
  int steps = 8;
  double noise = 0.01;
  // A region of the screen (u in [u0, u1]) where the pattern has no modulation or saturates.
  double flat_u0 = 2, flat_u1 = 2;
  double bright_u0 = 2, bright_u1 = 2;
};

std::vector<cv::Mat> capture(const Scene& s, const CaptureOptions& o) {
  const auto& in = s.camera.intrinsics();
  std::vector<cv::Mat> out;
  std::mt19937 rng(7);
  std::normal_distribution<float> noise(0.0f, float(o.noise));
  const display::DisplayCalibration& d = s.set.nominal.display;
  for (int k = 0; k < o.steps; ++k) {
    cv::Mat img(in.height, in.width, CV_32FC3, cv::Scalar::all(0.02));
    for (int y = 0; y < in.height; ++y)
      for (int x = 0; x < in.width; ++x) {
        Eigen::Vector3d p;
        if (!s.camera.panel_point(Eigen::Vector2d(x, y), p)) continue;
        const double u = p.x() / d.width_m() + 0.5, v = p.y() / d.height_m() + 0.5;
        if (u < 0 || u > 1 || v < 0 || v > 1) continue;
        double level = 0.4 + 0.3 * std::cos(kTwoPi * (true_psi(u, v) - double(k) / o.steps));
        if (u > o.flat_u0 && u < o.flat_u1) level = 0.4;
        if (u > o.bright_u0 && u < o.bright_u1) level = 1.0;
        auto& px = img.at<cv::Vec3f>(y, x);
        for (int c = 0; c < 3; ++c) px[c] = std::clamp(float(level) + noise(rng), 0.0f, 1.0f);
      }
    out.push_back(img);
  }
  return out;
}

TEST(PhaseDecoding, RecoversThePhaseWhereTheCameraLooks) {
  const Scene s = make_scene();
  for (int steps : {4, 8}) {
    CaptureOptions o;
    o.steps = steps;
    const DecodedPhase decoded = decode_phase(capture(s, o), s.registration, s.set);
    ASSERT_GT(decoded.samples.size(), 1000u) << steps;
    double sum2 = 0, worst = 0;
    for (const auto& q : decoded.samples) {
      const double e = wrapped(q.psi - true_psi(q.u, q.v));
      sum2 += e * e;
      worst = std::max(worst, std::abs(e));
      ASSERT_GE(q.psi, 0.0f);
      ASSERT_LT(q.psi, 1.0f);
    }
    const double rms = std::sqrt(sum2 / double(decoded.samples.size()));
    EXPECT_LT(rms, 0.005) << steps << " steps";
    EXPECT_LT(worst, 0.03) << steps << " steps";
    // The modulation b / a of the pattern, 0.3 / 0.4.
    EXPECT_NEAR(decoded.median_modulation, 0.75, 0.05) << steps;
    ASSERT_EQ(decoded.step_correlation.size(), size_t(steps));
    for (double c : decoded.step_correlation) EXPECT_GT(c, 0.95) << steps;
    // Nearly every block on the usable panel gave a sample.
    EXPECT_GT(double(decoded.samples.size()), 0.9 * double(decoded.blocks_on_panel));
  }
}

TEST(PhaseDecoding, SamplesCoverThePanelTheCameraSees) {
  const Scene s = make_scene();
  const DecodedPhase decoded = decode_phase(capture(s, {}), s.registration, s.set);
  float umin = 1, umax = 0, vmin = 1, vmax = 0;
  for (const auto& q : decoded.samples) {
    umin = std::min(umin, q.u), umax = std::max(umax, q.u);
    vmin = std::min(vmin, q.v), vmax = std::max(vmax, q.v);
  }
  // The whole screen is in the photo; only the margin (1 %) and the corner markers are left out.
  EXPECT_LT(umin, 0.03f);
  EXPECT_GT(umax, 0.97f);
  EXPECT_LT(vmin, 0.03f);
  EXPECT_GT(vmax, 0.97f);
  for (const auto& q : decoded.samples) {
    ASSERT_TRUE(q.u > 0.01f && q.u < 0.99f && q.v > 0.01f && q.v < 0.99f);
    ASSERT_FALSE(s.set.under_marker(q.u, q.v, s.set.markers.quiet_px));
  }
}

TEST(PhaseDecoding, LeavesOutFlatAndSaturatedRegionsAndCountsThem) {
  const Scene s = make_scene();
  CaptureOptions o;
  o.flat_u0 = 0.2, o.flat_u1 = 0.35;      // no modulation (bezel, defocus)
  o.bright_u0 = 0.6, o.bright_u1 = 0.75;  // saturated (glare)
  const DecodedPhase decoded = decode_phase(capture(s, o), s.registration, s.set);
  EXPECT_GT(decoded.blocks_low_modulation, 100);
  EXPECT_GT(decoded.blocks_clipped, 100);
  long inside = 0;
  for (const auto& q : decoded.samples) {
    // Blocks wholly inside either region give no sample.
    if ((q.u > 0.22f && q.u < 0.33f) || (q.u > 0.62f && q.u < 0.73f)) ++inside;
    EXPECT_LT(std::abs(wrapped(q.psi - true_psi(q.u, q.v))), 0.05);
  }
  EXPECT_EQ(inside, 0);
}

TEST(PhaseDecoding, ACaptureOfAnotherStepShowsInItsCorrelation) {
  const Scene s = make_scene();
  std::vector<cv::Mat> captures = capture(s, {});
  std::swap(captures[2], captures[6]);  // half a period apart: anti-correlated
  const DecodedPhase decoded = decode_phase(captures, s.registration, s.set);
  EXPECT_LT(decoded.step_correlation[2], 0.5);
  EXPECT_LT(decoded.step_correlation[6], 0.5);
  EXPECT_GT(decoded.step_correlation[0], 0.5);
}

}  // namespace
}  // namespace lfd::calib
