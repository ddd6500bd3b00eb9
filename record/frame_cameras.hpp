#pragma once
// Where the camera is in each frame of a recording (docs/record.md "Camera paths"): held still,
// a turntable (the scene's framing turned about its focal point and its up axis, one turn over
// the frames, distance and height kept), an orbit swing (the same turn, a smooth back-and-forth
// of +-DEG/2 that loops), or a keyframed path (render/camera_path.hpp) at the frames' times.
#include <optional>
#include <string>

#include "render/camera_path.hpp"
#include "scene/scene.hpp"

namespace lfd::record {

enum class PathKind { kStill, kTurntable, kOrbit, kKeyframes };

struct CameraMotion {
  PathKind kind = PathKind::kStill;
  double orbit_deg = 0.0;                  // kOrbit: the swing's full width
  render::CameraPath keyframes;            // kKeyframes
  std::optional<render::CameraSpec> still; // kStill: the camera held (else the scene's framing)
};

// "turntable", "orbit:DEG" (0 < DEG <= 360) or a camera path file (lfd keyframes or nerfstudio's
// camera_path.json); an empty `path` holds `still` (or the framing) still. InputError naming
// `option` or the file's field.
CameraMotion parse_camera_motion(const std::string& path, std::optional<render::CameraSpec> still,
                                 const std::string& option = "--path");

// The frames a recording has when the user gives no count: a keyframed path's duration at
// `fps` (its last keyframe included), else `seconds_default` seconds.
int default_frame_count(const CameraMotion& motion, int fps, double seconds_default = 4.0);

// The camera of frame `frame` of `frames` at `fps`, for views of `aspect` (width / height): the
// scene frames turntables, orbits and the still default; a path without a focus distance
// (nerfstudio's) is focused where the camera's axis passes the framed focal point.
render::CameraSpec frame_camera(const CameraMotion& motion, const scene::Scene& scene, int frame, int frames,
                                int fps, float aspect);

}  // namespace lfd::record
