#include "render/camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::render {
namespace {

using nlohmann::json;

// Python's json (nerfstudio's writer) spells non-finite numbers NaN, Infinity and -Infinity,
// which JSON has not: outside strings they become null, so the field's check names them.
std::string non_finite_as_null(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < text.size()) out += text[++i];
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    bool replaced = false;
    for (const std::string_view word : {"NaN", "Infinity", "-Infinity"})
      if (text.compare(i, word.size(), word) == 0) {
        out += "null";
        i += word.size() - 1;
        replaced = true;
        break;
      }
    if (!replaced) out += c;
  }
  return out;
}

double read_time(const json& key, const std::string& source, const std::string& field) {
  const auto it = key.find("time_s");
  require_field(it != key.end(), source, field + ".time_s", "missing");
  require_field(it->is_number() && std::isfinite(it->get<double>()), source, field + ".time_s",
                "must be a finite number");
  return it->get<double>();
}

// lfd keyframes: each one cam.json's fields (parse_camera_json checks them) and a time.
CameraPath lfd_keyframes(const json& j, const std::string& source) {
  const auto list = j.find("keyframes");
  require_field(list != j.end() && list->is_array(), source, "keyframes", "must be an array");
  require_field(!list->empty(), source, "keyframes", "none");
  CameraPath path;
  for (size_t i = 0; i < list->size(); ++i) {
    const std::string field = fmt::format("keyframes[{}]", i);
    const json& key = (*list)[i];
    require_field(key.is_object(), source, field, "must be an object");
    json camera = key;
    camera.erase("time_s");
    path.keyframes.push_back({read_time(key, source, field), parse_camera_json(camera.dump(), source + ": " + field)});
  }
  return path;
}

// nerfstudio's camera_to_world: 16 numbers row-major (or 4 rows of 4), OpenGL axes (x right, y
// up, the camera looking down -z).
CameraSpec nerfstudio_camera(const json& key, const std::string& source, const std::string& field) {
  require_field(key.is_object(), source, field, "must be an object");
  const auto m = key.find("camera_to_world");
  const std::string mfield = field + ".camera_to_world";
  require_field(m != key.end(), source, mfield, "missing");
  std::vector<double> v;
  if (m->is_array() && m->size() == 4 && (*m)[0].is_array()) {
    for (const json& row : *m) {
      require_field(row.is_array() && row.size() == 4, source, mfield, "must be 16 numbers (a 4x4 matrix)");
      for (const json& x : row) v.push_back(x.is_number() ? x.get<double>() : NAN);
    }
  } else {
    require_field(m->is_array() && m->size() == 16, source, mfield, "must be 16 numbers (a 4x4 matrix)");
    for (const json& x : *m) {
      require_field(x.is_number() || x.is_null(), source, mfield, "must be 16 numbers (a 4x4 matrix)");
      v.push_back(x.is_number() ? x.get<double>() : NAN);  // null: a NaN or infinity in the file
    }
  }
  // Finite, and within a float's range (the cameras are floats).
  for (double x : v)
    require_field(std::isfinite(x) && std::abs(x) < 1e30, source, mfield, "must be finite (it holds NaN or infinity)");
  const auto at = [&](int r, int c) { return float(v[size_t(r) * 4 + c]); };
  CameraSpec s;
  s.position = {at(0, 3), at(1, 3), at(2, 3)};
  const glm::vec3 back{at(0, 2), at(1, 2), at(2, 2)}, up{at(0, 1), at(1, 1), at(2, 1)};
  require_field(glm::length(back) > 1e-6f && glm::length(up) > 1e-6f &&
                    glm::length(glm::cross(back, up)) > 1e-6f * glm::length(back) * glm::length(up),
                source, mfield, "its rotation is degenerate");
  s.look_at = s.position - glm::normalize(back);  // one unit ahead: the recorder sets the focus
  s.up = glm::normalize(up);
  const auto fov = key.find("fov");
  require_field(fov != key.end(), source, field + ".fov", "missing");
  require_field(fov->is_number() && fov->get<double>() > 0.0 && fov->get<double>() < 178.0, source,
                field + ".fov", "must be a number in (0, 178)");
  s.fov_y_deg = fov->get<float>();
  return s;
}

CameraPath nerfstudio_path(const json& j, const std::string& source) {
  const json& list = j["camera_path"];
  require_field(list.is_array(), source, "camera_path", "must be an array");
  require_field(!list.empty(), source, "camera_path", "none");
  CameraPath path;
  path.focus_given = false;
  if (const auto fps = j.find("fps"); fps != j.end()) {
    require_field(fps->is_number() && fps->get<double>() > 0.0 && fps->get<double>() <= 1000.0, source, "fps",
                  "must be a number in (0, 1000]");
    path.frame_rate = fps->get<double>();
  } else if (const auto seconds = j.find("seconds"); seconds != j.end()) {
    require_field(seconds->is_number() && seconds->get<double>() > 0.0 && std::isfinite(seconds->get<double>()),
                  source, "seconds", "must be a positive number");
    path.frame_rate = double(list.size()) / seconds->get<double>();
  }
  const double rate = path.frame_rate > 0.0 ? path.frame_rate : 30.0;
  for (size_t i = 0; i < list.size(); ++i)
    path.keyframes.push_back({double(i) / rate, nerfstudio_camera(list[i], source, fmt::format("camera_path[{}]", i))});
  return path;
}

// Cubic Hermite with Catmull-Rom tangents over uneven times: C1 through every keyframe.
template <typename T>
T hermite(const std::vector<CameraKeyframe>& k, size_t i, double t, T (*get)(const CameraSpec&)) {
  const size_t n = k.size();
  const auto tangent = [&](size_t j) {
    const size_t a = j == 0 ? 0 : j - 1, b = std::min(j + 1, n - 1);
    return (get(k[b].camera) - get(k[a].camera)) / float(k[b].time_s - k[a].time_s);
  };
  const double dt = k[i + 1].time_s - k[i].time_s, s = (t - k[i].time_s) / dt;
  const double s2 = s * s, s3 = s2 * s;
  const float h00 = float(2 * s3 - 3 * s2 + 1), h10 = float((s3 - 2 * s2 + s) * dt),
              h01 = float(-2 * s3 + 3 * s2), h11 = float((s3 - s2) * dt);
  return h00 * get(k[i].camera) + h10 * tangent(i) + h01 * get(k[i + 1].camera) + h11 * tangent(i + 1);
}

glm::vec3 position_of(const CameraSpec& c) { return c.position; }
glm::vec3 look_at_of(const CameraSpec& c) { return c.look_at; }
glm::vec3 up_of(const CameraSpec& c) { return c.up; }
float fov_of(const CameraSpec& c) { return c.fov_y_deg; }

}  // namespace

CameraSpec CameraPath::at(double time_s) const {
  const auto& k = keyframes;
  if (k.size() == 1 || time_s <= k.front().time_s) return k.front().camera;
  if (time_s >= k.back().time_s) return k.back().camera;
  const size_t i = size_t(std::upper_bound(k.begin(), k.end(), time_s,
                                           [](double t, const CameraKeyframe& f) { return t < f.time_s; }) -
                          k.begin()) - 1;
  CameraSpec s = k[i].camera;
  s.position = hermite(k, i, time_s, position_of);
  s.look_at = hermite(k, i, time_s, look_at_of);
  s.fov_y_deg = std::clamp(hermite(k, i, time_s, fov_of), 1e-3f, 177.0f);
  // The up vector only needs a direction off the viewing axis; fall back to the nearer key's.
  const glm::vec3 up = hermite(k, i, time_s, up_of), forward = s.look_at - s.position;
  s.up = glm::length(glm::cross(up, forward)) > 1e-6f * glm::length(forward) ? glm::normalize(up)
                                                                            : k[i].camera.up;
  if (glm::length(forward) == 0.0f) s.look_at = s.position + (k[i].camera.look_at - k[i].camera.position);
  const bool same_size = std::all_of(k.begin(), k.end(), [&](const CameraKeyframe& f) {
    return f.camera.width == k[0].camera.width && f.camera.height == k[0].camera.height;
  });
  if (!same_size) s.width = s.height = std::nullopt;
  return s;
}

CameraPath parse_camera_path_json(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(non_finite_as_null(text));
  } catch (const json::exception& e) {
    throw_input_error("{}: not valid JSON ({})", source, e.what());
  }
  if (!j.is_object()) throw_input_error("{}: expected a JSON object (lfd keyframes or a nerfstudio camera path)", source);
  // nerfstudio's files carry its viewer's "keyframes" too; its "camera_path" is what it renders.
  CameraPath path = j.contains("camera_path") ? nerfstudio_path(j, source) : lfd_keyframes(j, source);
  for (size_t i = 1; i < path.keyframes.size(); ++i)
    require_field(path.keyframes[i].time_s > path.keyframes[i - 1].time_s, source,
                  fmt::format("keyframes[{}].time_s", i), "must be later than the keyframe before");
  return path;
}

CameraPath read_camera_path(const std::filesystem::path& path) {
  return parse_camera_path_json(read_text_file(path), path.string());
}

std::string camera_path_json_text(const CameraPath& path) {
  json keys = json::array();
  for (const CameraKeyframe& k : path.keyframes) {
    json key = json::parse(camera_json_text(k.camera));
    key["time_s"] = k.time_s;
    keys.push_back(key);
  }
  return json{{"keyframes", keys}}.dump(2) + "\n";
}

}  // namespace lfd::render
