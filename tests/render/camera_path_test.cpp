// Camera paths (render/camera_path.hpp): keyframes are passed through at their times, the
// interpolation is the straight line for evenly timed collinear keys, nerfstudio's matrices give
// the camera they describe, and every bad file names its field.
#include "render/camera_path.hpp"

#include <string>

#include <gtest/gtest.h>

#include "util/error.hpp"

namespace lfd::render {
namespace {

const char* kThreeKeys = R"({"keyframes": [
  {"time_s": 0, "position": [0, 0, -4], "look_at": [0, 0, 0], "fov_y_deg": 40},
  {"time_s": 1, "position": [1, 0, -4], "look_at": [1, 0, 0], "fov_y_deg": 40},
  {"time_s": 2, "position": [2, 0, -4], "look_at": [2, 0, 0], "fov_y_deg": 40}]})";

std::string error_of(const std::string& text) {
  try {
    parse_camera_path_json(text, "path.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CameraPath, KeyframesArePassedThroughAtTheirTimes) {
  const CameraPath path = parse_camera_path_json(kThreeKeys, "path.json");
  ASSERT_EQ(path.keyframes.size(), 3u);
  EXPECT_TRUE(path.focus_given);
  EXPECT_DOUBLE_EQ(path.duration_s(), 2.0);
  for (const CameraKeyframe& k : path.keyframes) {
    const CameraSpec s = path.at(k.time_s);
    EXPECT_FLOAT_EQ(s.position.x, k.camera.position.x);
    EXPECT_FLOAT_EQ(s.look_at.x, k.camera.look_at.x);
  }
  // Clamped outside the path.
  EXPECT_FLOAT_EQ(path.at(-1.0).position.x, 0.0f);
  EXPECT_FLOAT_EQ(path.at(5.0).position.x, 2.0f);
}

TEST(CameraPath, EvenlyTimedCollinearKeysMoveAtConstantSpeed) {
  const CameraPath path = parse_camera_path_json(kThreeKeys, "path.json");
  for (double t : {0.25, 0.5, 0.8, 1.3, 1.9}) {
    const CameraSpec s = path.at(t);
    EXPECT_NEAR(s.position.x, t, 1e-5) << t;
    EXPECT_NEAR(s.position.z, -4.0, 1e-5) << t;
    EXPECT_NEAR(s.fov_y_deg, 40.0, 1e-4) << t;
    EXPECT_NEAR(s.up.y, 1.0, 1e-6) << t;
  }
}

TEST(CameraPath, TheInterpolationIsSmoothThroughAKeyframe) {
  // A corner at t = 1: the velocity just before and just after agree (C1), unlike a polyline's.
  const CameraPath path = parse_camera_path_json(R"({"keyframes": [
    {"time_s": 0, "position": [0, 0, -4], "look_at": [0, 0, 0], "fov_y_deg": 40},
    {"time_s": 1, "position": [1, 0, -4], "look_at": [0, 0, 0], "fov_y_deg": 40},
    {"time_s": 2, "position": [1, 1, -4], "look_at": [0, 0, 0], "fov_y_deg": 40}]})",
                                                 "path.json");
  const double h = 1e-3;
  const glm::vec3 before = (path.at(1.0).position - path.at(1.0 - h).position) / float(h);
  const glm::vec3 after = (path.at(1.0 + h).position - path.at(1.0).position) / float(h);
  EXPECT_NEAR(before.x, after.x, 0.01);
  EXPECT_NEAR(before.y, after.y, 0.01);
}

TEST(CameraPath, ANerfstudioPoseGivesTheCameraItDescribes) {
  // camera_to_world: the camera at (1, 2, 3) turned 90 degrees about y: its -z axis (the view)
  // points along world -x, its y axis (up) along world +y.
  const CameraPath path = parse_camera_path_json(R"({"fps": 24, "seconds": 1, "keyframes": [{"matrix": "ignored"}],
    "camera_path": [
      {"camera_to_world": [0, 0, 1, 1,  0, 1, 0, 2,  -1, 0, 0, 3,  0, 0, 0, 1], "fov": 50, "aspect": 1.5},
      {"camera_to_world": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 5], [0, 0, 0, 1]], "fov": 30}]})",
                                                 "camera_path.json");
  ASSERT_EQ(path.keyframes.size(), 2u);
  EXPECT_FALSE(path.focus_given);
  EXPECT_DOUBLE_EQ(path.frame_rate, 24.0);
  EXPECT_DOUBLE_EQ(path.keyframes[1].time_s, 1.0 / 24.0);
  const CameraSpec& a = path.keyframes[0].camera;
  EXPECT_EQ(a.position, glm::vec3(1, 2, 3));
  EXPECT_NEAR(glm::length(a.look_at - a.position - glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(a.up - glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_FLOAT_EQ(a.fov_y_deg, 50.0f);
  const CameraSpec& b = path.keyframes[1].camera;
  EXPECT_EQ(b.position, glm::vec3(0, 0, 5));
  EXPECT_NEAR(glm::length(b.look_at - glm::vec3(0, 0, 4)), 0.0f, 1e-6f);
}

TEST(CameraPath, WrittenKeyframesReadBack) {
  const CameraPath path = parse_camera_path_json(kThreeKeys, "path.json");
  const CameraPath again = parse_camera_path_json(camera_path_json_text(path), "again.json");
  ASSERT_EQ(again.keyframes.size(), 3u);
  EXPECT_DOUBLE_EQ(again.keyframes[2].time_s, 2.0);
  EXPECT_EQ(again.keyframes[2].camera.position, path.keyframes[2].camera.position);
}

TEST(CameraPath, BadFilesNameTheFileAndTheField) {
  EXPECT_EQ(error_of(R"({"keyframes": []})"), "path.json: keyframes: none");
  EXPECT_EQ(error_of(R"({"camera_path": []})"), "path.json: camera_path: none");
  EXPECT_EQ(error_of(R"({"camera_path": [{"camera_to_world": [1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0], "fov": 50}]})"),
            "path.json: camera_path[0].camera_to_world: must be 16 numbers (a 4x4 matrix)");
  EXPECT_EQ(error_of(R"({"camera_path": [{"camera_to_world": [1, 0, 0, NaN, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], "fov": 50}]})"),
            "path.json: camera_path[0].camera_to_world: must be finite (it holds NaN or infinity)");
  EXPECT_EQ(error_of(R"({"camera_path": [{"camera_to_world": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}]})"),
            "path.json: camera_path[0].fov: missing");
  EXPECT_EQ(error_of(R"({"keyframes": [{"time_s": 0, "position": [0, NaN, 1], "look_at": [0, 0, 0], "fov_y_deg": 40}]})"),
            "path.json: keyframes[0]: position: must be an array of 3 numbers");
  EXPECT_EQ(error_of(R"({"keyframes": [{"position": [0, 0, 1], "look_at": [0, 0, 0], "fov_y_deg": 40}]})"),
            "path.json: keyframes[0].time_s: missing");
  EXPECT_EQ(error_of(R"({"keyframes": [
    {"time_s": 1, "position": [0, 0, 1], "look_at": [0, 0, 0], "fov_y_deg": 40},
    {"time_s": 1, "position": [0, 0, 2], "look_at": [0, 0, 0], "fov_y_deg": 40}]})"),
            "path.json: keyframes[1].time_s: must be later than the keyframe before");
  EXPECT_NE(error_of("[1, 2]").find("path.json: expected a JSON object"), std::string::npos);
  EXPECT_NE(error_of("{").find("path.json: not valid JSON"), std::string::npos);
  // A string holding NaN is left alone (and then refused as a string).
  EXPECT_EQ(error_of(R"({"camera_path": [{"camera_to_world": "NaN", "fov": 50}]})"),
            "path.json: camera_path[0].camera_to_world: must be 16 numbers (a 4x4 matrix)");
}

}  // namespace
}  // namespace lfd::render
