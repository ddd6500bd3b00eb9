#include "record/frame_cameras.hpp"

#include <cmath>
#include <filesystem>

#include <glm/glm.hpp>

#include "lightfield/scene_framing.hpp"
#include "util/error.hpp"

namespace lfd::record {

CameraMotion parse_camera_motion(const std::string& path, std::optional<render::CameraSpec> still,
                                 const std::string& option) {
  CameraMotion m;
  m.still = still;
  if (path.empty()) return m;
  if (still) throw_input_error("{}: a moving camera; --camera holds one still (give one of them)", option);
  if (path == "turntable") {
    m.kind = PathKind::kTurntable;
  } else if (path.starts_with("orbit:")) {
    m.kind = PathKind::kOrbit;
    const std::string deg = path.substr(6);
    size_t used = 0;
    try {
      m.orbit_deg = std::stod(deg, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != deg.size() || !(m.orbit_deg > 0.0 && m.orbit_deg <= 360.0))
      throw_input_error("{}: '{}': orbit:DEG needs a swing in (0, 360] degrees", option, path);
  } else {
    if (!std::filesystem::exists(path))
      throw_input_error("{}: '{}' is neither turntable, orbit:DEG nor a camera path file", option, path);
    m.kind = PathKind::kKeyframes;
    m.keyframes = render::read_camera_path(path);
  }
  return m;
}

int default_frame_count(const CameraMotion& motion, int fps, double seconds_default) {
  if (motion.kind == PathKind::kKeyframes) return int(std::floor(motion.keyframes.duration_s() * fps + 1e-9)) + 1;
  return std::max(1, int(std::lround(seconds_default * fps)));
}

namespace {

// A camera that says where it looks but not how far, focused where its axis passes the framed
// focal point (at its distance along the axis; the framing's distance when that is behind it).
render::CameraSpec focus_on_scene(render::CameraSpec s, const render::CameraSpec& framing) {
  const glm::vec3 forward = glm::normalize(s.look_at - s.position);
  float distance = glm::dot(framing.look_at - s.position, forward);
  if (!(distance > 1e-4f)) distance = glm::length(framing.look_at - framing.position);
  s.look_at = s.position + forward * distance;
  return s;
}

// The framing turned by `degrees` about the up axis through its focal point: a turntable keeps
// the distance, the height and the focus (the framing of each angle alone would refit them).
render::CameraSpec turned(render::CameraSpec s, double degrees) {
  const glm::vec3 axis = glm::normalize(s.up), offset = s.position - s.look_at;
  const float a = float(degrees * M_PI / 180.0);
  // Rodrigues' rotation of the offset about the axis.
  const glm::vec3 rotated = offset * std::cos(a) + glm::cross(axis, offset) * std::sin(a) +
                            axis * glm::dot(axis, offset) * (1.0f - std::cos(a));
  s.position = s.look_at + rotated;
  return s;
}

}  // namespace

render::CameraSpec frame_camera(const CameraMotion& m, const scene::Scene& scene, int frame, int frames, int fps,
                                float aspect) {
  switch (m.kind) {
    case PathKind::kStill:
      return m.still ? *m.still : lightfield::scene_framing(scene, render::kDefaultFovYDeg, 0.0f, aspect);
    case PathKind::kTurntable:
      return turned(lightfield::scene_framing(scene, render::kDefaultFovYDeg, 0.0f, aspect), 360.0 * frame / frames);
    case PathKind::kOrbit: {
      // A sine swing: smooth at its ends, and the last frame leads back into the first.
      const double phase = 2.0 * M_PI * frame / frames;
      return turned(lightfield::scene_framing(scene, render::kDefaultFovYDeg, 0.0f, aspect),
                    0.5 * m.orbit_deg * std::sin(phase));
    }
    case PathKind::kKeyframes: {
      const double t = m.keyframes.keyframes.front().time_s + double(frame) / fps;
      const render::CameraSpec s = m.keyframes.at(t);
      if (m.keyframes.focus_given) return s;
      return focus_on_scene(s, lightfield::scene_framing(scene, s.fov_y_deg, 0.0f, aspect));
    }
  }
  throw std::logic_error("frame_camera: unknown path kind");
}

}  // namespace lfd::record
