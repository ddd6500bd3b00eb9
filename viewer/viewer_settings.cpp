#include "viewer/viewer_settings.hpp"

#include <cstdlib>

#include <nlohmann/json.hpp>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::viewer {
namespace {

using nlohmann::json;

template <typename T>
void read_field(const json& j, const char* field, T& value, const std::string& source) {
  if (!j.contains(field)) return;
  try {
    value = j.at(field).get<T>();
  } catch (const json::exception&) {
    throw_input_error("{}: {}: has the wrong type", source, field);
  }
}

}  // namespace

std::string method_name(Method m) {
  return m == Method::kG2lf ? "g2lf" : m == Method::kG2lfDirect ? "g2lf-direct" : "per-view";
}

Method parse_method(const std::string& name) {
  if (name == "g2lf") return Method::kG2lf;
  if (name == "per-view") return Method::kPerView;
  if (name == "g2lf-direct") return Method::kG2lfDirect;
  throw_input_error("method: '{}' is not g2lf, g2lf-direct or per-view", name);
}

void ViewerSettings::check(const std::string& source) const {
  try {
    g2lf.check();
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
  require_field(views == 0 || (views >= 1 && views <= 256), source, "views", "must be 0 (the display's) or 1..256");
  require_field(view_cone_deg == 0.0f || (view_cone_deg > 0.0f && view_cone_deg < 170.0f), source,
                "view_cone_deg", "must be 0 (the display's) or in (0, 170)");
  require_field(focal_fraction > 0.01f && focal_fraction < 100.0f, source, "focal_fraction", "must lie in (0.01, 100)");
  require_field(depthiness > 0.0f && depthiness <= 4.0f, source, "depthiness", "must lie in (0, 4]");
  require_field(view_height_px >= 16 && view_height_px <= 4096, source, "view_height_px", "must lie in 16..4096");
  for (int c = 0; c < 3; ++c)
    require_field(background[c] >= 0.0f && background[c] <= 1.0f, source, "background", "components must lie in [0, 1]");
}

std::string settings_to_json(const ViewerSettings& s) {
  json j;
  j["method"] = method_name(s.method);
  j["chunks"] = s.g2lf.chunks;
  j["plane_scale"] = s.g2lf.plane_scale;
  j["d_shift"] = s.g2lf.d_shift;
  j["filter"] = s.g2lf.filter == render::PlaneFilter::kBilinear ? "bilinear" : "nearest";
  j["precision"] = s.g2lf.precision == render::PlanePrecision::kF32 ? "f32" : "u8";
  j["binning"] = s.g2lf.binning == render::ChunkBinning::kQuantile ? "quantile" : "mixed";
  j["adaptive_filter"] = s.g2lf.adaptive_filter;
  j["views"] = s.views;
  j["view_cone_deg"] = s.view_cone_deg;
  j["focal_fraction"] = s.focal_fraction;
  j["depthiness"] = s.depthiness;
  j["background"] = {s.background.r, s.background.g, s.background.b};
  j["view_height_px"] = s.view_height_px;
  return j.dump(2) + "\n";
}

ViewerSettings settings_from_json(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw_input_error("{}: not JSON ({})", source, e.what());
  }
  if (!j.is_object()) throw_input_error("{}: expected a JSON object", source);
  ViewerSettings s;
  std::string method = method_name(s.method), filter = "nearest", precision = "u8", binning = "mixed";
  read_field(j, "method", method, source);
  read_field(j, "chunks", s.g2lf.chunks, source);
  read_field(j, "plane_scale", s.g2lf.plane_scale, source);
  read_field(j, "d_shift", s.g2lf.d_shift, source);
  read_field(j, "filter", filter, source);
  read_field(j, "precision", precision, source);
  read_field(j, "binning", binning, source);
  read_field(j, "adaptive_filter", s.g2lf.adaptive_filter, source);
  read_field(j, "views", s.views, source);
  read_field(j, "view_cone_deg", s.view_cone_deg, source);
  read_field(j, "focal_fraction", s.focal_fraction, source);
  read_field(j, "depthiness", s.depthiness, source);
  read_field(j, "view_height_px", s.view_height_px, source);
  if (j.contains("background")) {
    std::array<float, 3> bg{};
    read_field(j, "background", bg, source);
    s.background = glm::vec3(bg[0], bg[1], bg[2]);
  }
  try {
    s.method = parse_method(method);
    s.g2lf.filter = render::parse_plane_filter(filter);
    s.g2lf.precision = render::parse_plane_precision(precision);
    s.g2lf.binning = render::parse_chunk_binning(binning);
  } catch (const InputError& e) {
    throw InputError(source + ": " + e.what());
  }
  s.check(source);
  return s;
}

std::filesystem::path settings_path_for_display(const std::string& display_key) {
  std::string key;
  for (char c : display_key)
    key += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  if (key.empty()) key = "display";
  std::filesystem::path base;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    base = xdg;
  else if (const char* home = std::getenv("HOME"); home && *home)
    base = std::filesystem::path(home) / ".config";
  else
    base = std::filesystem::temp_directory_path();
  return base / "lfd" / "viewer" / (key + ".json");
}

ViewerSettings load_settings(const std::filesystem::path& path, const ViewerSettings& defaults) {
  if (!std::filesystem::exists(path)) return defaults;
  return settings_from_json(read_text_file(path), path.string());
}

void save_settings(const std::filesystem::path& path, const ViewerSettings& s) {
  write_text_atomic(path, settings_to_json(s));
}

}  // namespace lfd::viewer
