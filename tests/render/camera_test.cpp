#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "render/camera.hpp"
#include "render/camera_json.hpp"
#include "util/error.hpp"

namespace lfd::render {
namespace {

TEST(Camera, LookAtPointProjectsToTheImageCentre) {
  const Camera c = make_look_at_camera({1, 2, 3}, {4, 0, -2}, {0, 1, 0}, 0.8f, 64, 48);
  const glm::vec2 px = c.project_px({4, 0, -2});
  EXPECT_NEAR(px.x, (64 - 1) / 2.0f, 1e-4f);  // ndc2Pix: centre of pixel i is i
  EXPECT_NEAR(px.y, (48 - 1) / 2.0f, 1e-4f);
}

TEST(Camera, AxesAreRightDownForwardWithUpOnTop) {
  // Looking down -z with y up (OpenGL default view): right = +x, down = -y.
  const Camera c = make_look_at_camera({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 0.8f, 32, 32);
  EXPECT_NEAR(c.right().x, 1.0f, 1e-6f);
  EXPECT_NEAR(c.down().y, -1.0f, 1e-6f);
  EXPECT_NEAR(c.forward().z, -1.0f, 1e-6f);
  // A point above the target lands in the upper half (smaller row).
  EXPECT_LT(c.project_px({0, 1, 0}).y, 15.5f);
  EXPECT_GT(c.project_px({1, 0, 0}).x, 15.5f);
}

TEST(Camera, FovXFollowsAspectWithSquarePixels) {
  const Camera c = make_look_at_camera({0, 0, 0}, {0, 0, 1}, {0, -1, 0}, 0.9f, 200, 100);
  EXPECT_NEAR(c.tan_half_fov_x(), 2.0f * c.tan_half_fov_y(), 1e-5f);
  EXPECT_NEAR(c.focal_x_px(), c.focal_y_px(), 1e-3f);
}

TEST(Camera, ProjectionMatrixMatchesProjectNdc) {
  Camera c = make_look_at_camera({0.3f, 0, -1}, {0, 0.2f, 2}, {0, -1, 0}, 0.7f, 80, 60);
  c.shift_x_ndc = 0.17f;
  const glm::vec3 p(0.4f, -0.3f, 2.5f);
  const glm::vec4 clip = c.projection_matrix() * c.view_matrix() * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = c.project_ndc(p);
  EXPECT_NEAR(clip.x / clip.w, ndc.x, 1e-5f);
  EXPECT_NEAR(clip.y / clip.w, ndc.y, 1e-5f);
}

TEST(Camera, DegenerateInputIsRejected) {
  EXPECT_THROW(make_look_at_camera({0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 0.8f, 8, 8), InputError);
  EXPECT_THROW(make_look_at_camera({0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 0.8f, 8, 8), InputError);
  EXPECT_THROW(make_look_at_camera({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0.8f, 0, 8), InputError);
}

TEST(CameraJson, ReadsAllFields) {
  const auto s = parse_camera_json(
      R"({"position":[1,2,3],"look_at":[0,0,0],"up":[0,0,1],"fov_y_deg":30,"width":640,"height":360})",
      "cam.json");
  EXPECT_EQ(s.position, glm::vec3(1, 2, 3));
  EXPECT_EQ(s.up, glm::vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(s.fov_y_deg, 30.0f);
  EXPECT_EQ(*s.width, 640);
  EXPECT_EQ(*s.height, 360);
  const Camera c = camera_from_spec(s);
  EXPECT_EQ(c.width, 640);
  EXPECT_NEAR(c.fov_y_rad, 30.0f * float(M_PI) / 180.0f, 1e-6f);
}

void expect_error_naming(const std::string& text, const std::string& field) {
  try {
    parse_camera_json(text, "cam.json");
    FAIL() << "no error for " << text;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("cam.json"), std::string::npos) << msg;
    EXPECT_NE(msg.find(field), std::string::npos) << msg;
  }
}

TEST(CameraJson, BadFieldsNameFileAndField) {
  expect_error_naming(R"({"look_at":[0,0,0],"fov_y_deg":30})", "position");
  expect_error_naming(R"({"position":[1,2],"look_at":[0,0,0],"fov_y_deg":30})", "position");
  expect_error_naming(R"({"position":[1,2,"a"],"look_at":[0,0,0],"fov_y_deg":30})", "position");
  expect_error_naming(R"({"position":[1,2,3],"fov_y_deg":30})", "look_at");
  expect_error_naming(R"({"position":[1,2,3],"look_at":[0,0,0]})", "fov_y_deg");
  expect_error_naming(R"({"position":[1,2,3],"look_at":[0,0,0],"fov_y_deg":-5})", "fov_y_deg");
  expect_error_naming(R"({"position":[1,2,3],"look_at":[0,0,0],"fov_y_deg":30,"width":-1})", "width");
  expect_error_naming(R"({"position":[1,2,3],"look_at":[0,0,0],"fov_y_deg":30,"height":1.5})", "height");
  expect_error_naming(R"({"position":[1,2,3],"look_at":[1,2,3],"fov_y_deg":30})", "look_at");
  expect_error_naming(R"({"position":[0,0,0],"look_at":[0,1,0],"fov_y_deg":30})", "up");
  expect_error_naming(R"({"position":[0,0,0],)", "JSON");
  // Found by fuzz_cam_json: a number beyond double range escaped as nlohmann's out_of_range.
  expect_error_naming(R"({"position":[0,0,-31e308],"look_at":[0,0,0],"fov_y_deg":30})", "JSON");
}

TEST(CameraJson, MissingFileIsAnInputError) {
  EXPECT_THROW(read_camera_json("/nonexistent/cam.json"), InputError);
}

}  // namespace
}  // namespace lfd::render
