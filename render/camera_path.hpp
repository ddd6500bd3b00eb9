#pragma once
// Camera paths for `lfd record` (docs/record.md "Camera paths"): keyframed cameras in time, read
// from lfd's keyframe files (cam.json's fields plus a time) or nerfstudio's camera_path.json (its
// camera_to_world matrices and vertical fov, one camera per frame at its fps), and sampled at any
// time with a smooth (C1, cubic Hermite with Catmull-Rom tangents) interpolation.
#include <filesystem>
#include <string>
#include <vector>

#include "render/camera_json.hpp"

namespace lfd::render {

struct CameraKeyframe {
  double time_s = 0.0;
  CameraSpec camera;
};

struct CameraPath {
  std::vector<CameraKeyframe> keyframes;  // at least one, times strictly increasing
  // nerfstudio's cameras say where they look but not how far: the recorder focuses them on the
  // scene (docs/record.md). lfd keyframes focus at |look_at - position| like cam.json.
  bool focus_given = true;
  double frame_rate = 0.0;  // the file's own fps (nerfstudio), 0 when it says none

  double duration_s() const { return keyframes.back().time_s - keyframes.front().time_s; }
  // The camera at `time_s` (clamped to the path): positions, look-at points, up vectors and fov
  // each interpolated; the up vector renormalised. Keyframes keep their size fields only when all
  // agree.
  CameraSpec at(double time_s) const;
};

// lfd keyframes, {"keyframes": [{"time_s": T, <cam.json fields>}, ...]}, or nerfstudio's
// {"camera_path": [{"camera_to_world": [16 numbers, row-major], "fov": DEG}, ...], "fps": F}.
// InputError "<source>: <field>: <problem>" (e.g. "path.json: keyframes[2].position: must be
// finite", "camera_path[0].camera_to_world: must be 16 numbers (a 4x4 matrix)", "keyframes: none").
CameraPath parse_camera_path_json(const std::string& text, const std::string& source);
CameraPath read_camera_path(const std::filesystem::path& path);

// lfd keyframes text of a path (what parse_camera_path_json reads back).
std::string camera_path_json_text(const CameraPath& path);

}  // namespace lfd::render
