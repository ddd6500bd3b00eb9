// The viewer's pure parts: camera moves, input mapping and the per-display settings file.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "viewer/input.hpp"
#include "viewer/orbit_camera.hpp"
#include "viewer/viewer_settings.hpp"

namespace lfd::viewer {
namespace {

render::CameraSpec start_spec() {
  render::CameraSpec s;
  s.position = {0, 0, 5};
  s.look_at = {0, 0, 0};
  s.up = {0, 1, 0};
  s.fov_y_deg = 40;
  return s;
}

float elevation_deg(const render::CameraSpec& s) {
  const glm::vec3 d = glm::normalize(s.position - s.look_at);
  return glm::degrees(std::asin(glm::dot(d, glm::normalize(s.up))));
}

TEST(OrbitCamera, OrbitKeepsTheDistanceAndTurnsByTheAngle) {
  OrbitCamera c(start_spec());
  c.orbit(glm::radians(90.0f), 0.0f);
  EXPECT_NEAR(c.distance(), 5.0f, 1e-5);
  EXPECT_NEAR(std::abs(c.spec().position.x), 5.0f, 1e-4);  // a quarter turn about y
  EXPECT_NEAR(c.spec().position.z, 0.0f, 1e-4);
  c.orbit(0.0f, glm::radians(30.0f));
  EXPECT_NEAR(elevation_deg(c.spec()), 30.0f, 1e-3);
  EXPECT_NEAR(c.distance(), 5.0f, 1e-5);
}

TEST(OrbitCamera, PitchStopsShortOfThePole) {
  OrbitCamera c(start_spec());
  c.orbit(0.0f, glm::radians(170.0f));
  EXPECT_NEAR(elevation_deg(c.spec()), 85.0f, 1e-3);
  c.orbit(0.0f, glm::radians(-400.0f));
  EXPECT_NEAR(elevation_deg(c.spec()), -85.0f, 1e-3);
}

TEST(OrbitCamera, PanMovesCameraAndTargetTogetherByViewHeights) {
  OrbitCamera c(start_spec());
  c.pan(0.5f, 0.0f);  // half a view height: 0.5 * 2 * 5 * tan(20 deg)
  const float expected = 0.5f * 2.0f * 5.0f * std::tan(glm::radians(20.0f));
  EXPECT_NEAR(c.spec().position.x, -expected, 1e-5);
  EXPECT_NEAR(c.spec().look_at.x, -expected, 1e-5);
  EXPECT_NEAR(c.distance(), 5.0f, 1e-5);
}

TEST(OrbitCamera, ZoomScalesTheDistanceAndResetRestores) {
  OrbitCamera c(start_spec());
  c.zoom(10.0f);
  EXPECT_NEAR(c.distance(), 5.0f * std::exp(-1.0f), 1e-4);
  c.zoom(-10.0f);
  EXPECT_NEAR(c.distance(), 5.0f, 1e-4);
  c.orbit(1.0f, 0.3f);
  c.reset();
  EXPECT_EQ(c.spec().position, start_spec().position);
}

TEST(ViewerInput, DragAcrossTheWindowTurnsHalfAround) {
  struct Case {
    InputEvents in;
    float yaw_deg;  // expected turn of the camera about the up axis
  };
  InputEvents right_drag;
  right_drag.drag_dx_px = 400;  // a full window height of 400 px
  InputEvents arrows;
  arrows.orbit_keys_x = 1;  // one second of the right arrow: 90 degrees
  for (const auto& [in, yaw] : {Case{right_drag, -180.0f}, Case{arrows, 90.0f}}) {
    OrbitCamera c(start_spec());
    apply_input(in, 400, 1.0, c);
    const glm::vec3 p = c.spec().position;
    const float turned = glm::degrees(std::atan2(p.x, p.z));
    EXPECT_NEAR(std::abs(turned), std::abs(yaw) == 180.0f ? 180.0f : std::abs(yaw), 1e-2);
    if (std::abs(yaw) != 180.0f) {
      EXPECT_GT(turned * yaw, 0.0f);
    }
  }
  InputEvents none;
  EXPECT_FALSE(none.any());
  InputEvents reset;
  reset.reset = true;
  OrbitCamera c(start_spec());
  c.zoom(5);
  apply_input(reset, 400, 0.016, c);
  EXPECT_NEAR(c.distance(), 5.0f, 1e-5);
}

TEST(ViewerSettings, RoundTripsThroughTheConfigFile) {
  ViewerSettings s;
  s.method = Method::kPerView;
  s.g2lf.chunks = 128;
  s.g2lf.plane_scale = 2;
  s.g2lf.filter = render::PlaneFilter::kBilinear;
  s.g2lf.binning = render::ChunkBinning::kQuantile;
  s.views = 48;
  s.focal_fraction = 1.25f;
  s.depthiness = 0.7f;
  s.background = {0.1f, 0.2f, 0.3f};
  const auto dir = std::filesystem::temp_directory_path() / "lfd_viewer_settings_test";
  std::filesystem::remove_all(dir);
  const auto path = dir / "LKG-P01234.json";
  EXPECT_EQ(load_settings(path, s).g2lf.chunks, 128);  // no file: the defaults given
  save_settings(path, s);
  const ViewerSettings r = load_settings(path, ViewerSettings{});
  EXPECT_EQ(r.method, Method::kPerView);
  EXPECT_EQ(r.g2lf.chunks, 128);
  EXPECT_EQ(r.g2lf.plane_scale, 2);
  EXPECT_EQ(r.g2lf.filter, render::PlaneFilter::kBilinear);
  EXPECT_EQ(r.g2lf.binning, render::ChunkBinning::kQuantile);
  EXPECT_EQ(r.views, 48);
  EXPECT_FLOAT_EQ(r.focal_fraction, 1.25f);
  EXPECT_FLOAT_EQ(r.depthiness, 0.7f);
  EXPECT_FLOAT_EQ(r.background.b, 0.3f);
  std::filesystem::remove_all(dir);
}

TEST(ViewerSettings, BadFieldsAreNamed) {
  auto message = [](const std::string& text) {
    try {
      settings_from_json(text, "cfg.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(R"({"chunks": 0})").find("chunks"), std::string::npos);
  EXPECT_NE(message(R"({"depthiness": "deep"})").find("cfg.json: depthiness"), std::string::npos);
  EXPECT_NE(message(R"({"method": "raytrace"})").find("method"), std::string::npos);
  EXPECT_NE(message("{not json").find("cfg.json"), std::string::npos);
  EXPECT_NE(message(R"({"views": 1000})").find("views"), std::string::npos);
}

TEST(ViewerSettings, TheFileNameComesFromTheDisplayKey) {
  setenv("XDG_CONFIG_HOME", "/tmp/xdg-test", 1);
  EXPECT_EQ(settings_path_for_display("LKG-2K 04409/x"), std::filesystem::path("/tmp/xdg-test/lfd/viewer/LKG-2K_04409_x.json"));
  unsetenv("XDG_CONFIG_HOME");
}

}  // namespace
}  // namespace lfd::viewer
