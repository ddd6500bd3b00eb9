#include "render/camera_json.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "util/error.hpp"

namespace lfd::render {
namespace {

glm::vec3 read_vec3(const nlohmann::json& j, const std::string& source, const char* field) {
  const auto it = j.find(field);
  require_field(it != j.end(), source, field, "missing");
  require_field(it->is_array() && it->size() == 3, source, field, "must be an array of 3 numbers");
  glm::vec3 v;
  for (int i = 0; i < 3; ++i) {
    require_field((*it)[i].is_number(), source, field, "must be an array of 3 numbers");
    v[i] = (*it)[i].get<float>();
    require_field(std::isfinite(v[i]), source, field, "must be finite");
  }
  return v;
}

std::optional<int> read_size(const nlohmann::json& j, const std::string& source, const char* field) {
  const auto it = j.find(field);
  if (it == j.end()) return std::nullopt;
  require_field(it->is_number_integer() && it->get<long long>() > 0 && it->get<long long>() <= 32768,
                source, field, "must be an integer in [1, 32768]");
  return it->get<int>();
}

}  // namespace

CameraSpec parse_camera_json(const std::string& text, const std::string& source) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range: 1e999
    throw_input_error("{}: not valid JSON ({})", source, e.what());
  }
  if (!j.is_object()) throw_input_error("{}: expected a JSON object", source);
  CameraSpec s;
  s.position = read_vec3(j, source, "position");
  s.look_at = read_vec3(j, source, "look_at");
  if (j.contains("up")) s.up = read_vec3(j, source, "up");
  const auto fov = j.find("fov_y_deg");
  require_field(fov != j.end(), source, "fov_y_deg", "missing");
  require_field(fov->is_number() && fov->get<double>() > 0.0 && fov->get<double>() < 178.0, source,
                "fov_y_deg", "must be a number in (0, 178)");
  s.fov_y_deg = fov->get<float>();
  s.width = read_size(j, source, "width");
  s.height = read_size(j, source, "height");
  require_field(glm::length(s.look_at - s.position) > 0.0f, source, "look_at", "equals position");
  require_field(glm::length(glm::cross(s.look_at - s.position, s.up)) > 0.0f, source, "up",
                "is zero or parallel to the viewing direction");
  return s;
}

std::string camera_json_text(const CameraSpec& spec) {
  nlohmann::json j;
  j["position"] = {spec.position.x, spec.position.y, spec.position.z};
  j["look_at"] = {spec.look_at.x, spec.look_at.y, spec.look_at.z};
  j["up"] = {spec.up.x, spec.up.y, spec.up.z};
  j["fov_y_deg"] = spec.fov_y_deg;
  if (spec.width) j["width"] = *spec.width;
  if (spec.height) j["height"] = *spec.height;
  return j.dump(2) + "\n";
}

CameraSpec read_camera_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw_input_error("{}: cannot open camera file", path.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_camera_json(ss.str(), path.string());
}

Camera camera_from_spec(const CameraSpec& spec, std::optional<int> width, std::optional<int> height) {
  const int w = width ? *width : spec.width.value_or(512);
  const int h = height ? *height : spec.height.value_or(512);
  return make_look_at_camera(spec.position, spec.look_at, spec.up,
                             spec.fov_y_deg * float(M_PI) / 180.0f, w, h);
}

}  // namespace lfd::render
