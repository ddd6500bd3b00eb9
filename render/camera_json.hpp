#pragma once
// cam.json: {"position":[x,y,z],"look_at":[x,y,z],"up":[x,y,z],"fov_y_deg":f,"width":w,"height":h}.
// "up" defaults to [0,1,0]; width/height may be omitted when the caller supplies a size.
#include <filesystem>
#include <optional>
#include <string>

#include "render/camera.hpp"

namespace lfd::render {

struct CameraSpec {
  glm::vec3 position{0.0f};
  glm::vec3 look_at{0.0f, 0.0f, 1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 45.0f;
  std::optional<int> width;
  std::optional<int> height;
};

// Throws InputError "<file>: <field>: <problem>" for a missing or malformed field.
CameraSpec read_camera_json(const std::filesystem::path& path);
// Parses the JSON text; `source` names it in error messages.
CameraSpec parse_camera_json(const std::string& text, const std::string& source);

// cam.json text of a spec (what parse_camera_json reads back); the size only when it has one.
std::string camera_json_text(const CameraSpec& spec);

// The camera of a spec; `width`/`height` override the spec's size when given.
Camera camera_from_spec(const CameraSpec& spec, std::optional<int> width = {},
                        std::optional<int> height = {});

}  // namespace lfd::render
