#include "display/visual_json.hpp"

#include <cmath>
#include <iostream>
#include <optional>

#include "util/atomic_file.hpp"
#include "util/default_display.hpp"
#include "util/error.hpp"

namespace lfd::display {

namespace {

using ojson = nlohmann::ordered_json;

// A numeric field: {"value": x} as devices write it, or a bare number.
std::optional<double> read_number(const ojson& root, const char* key, const std::string& name) {
  auto it = root.find(key);
  if (it == root.end()) return std::nullopt;
  const ojson* node = &*it;
  if (node->is_object()) {
    auto v = node->find("value");
    require_field(v != node->end(), name, key, "has no \"value\"");
    node = &*v;
  }
  require_field(node->is_number(), name, key, "is not a number");
  const double value = node->get<double>();
  require_field(std::isfinite(value), name, key, "is not a finite number");
  return value;
}

int read_int(const ojson& root, const char* key, const std::string& name, int fallback) {
  auto v = read_number(root, key, name);
  if (!v) return fallback;
  require_field(*v == std::floor(*v) && std::abs(*v) < 1e9, name, key, "is not an integer");
  return static_cast<int>(*v);
}

double read_cell_value(const ojson& cell, const char* key, const std::string& name, size_t index) {
  const std::string field = "subpixelCells[" + std::to_string(index) + "]." + key;
  auto it = cell.find(key);
  require_field(it != cell.end(), name, field, "is missing");
  const ojson* node = &*it;
  if (node->is_object() && node->contains("value")) node = &(*node)["value"];
  require_field(node->is_number(), name, field, "is not a number");
  return node->get<double>();
}

// Keeps the stored form of a field when its value is unchanged, so files round-trip exactly.
void put_number(ojson& root, const char* key, double value) {
  auto it = root.find(key);
  if (it != root.end()) {
    const ojson& node = it->is_object() && it->contains("value") ? (*it)["value"] : *it;
    if (node.is_number() && node.get<double>() == value) return;
    if (it->is_object()) {
      (*it)["value"] = value;
      return;
    }
  }
  root[key] = ojson{{"value", value}};
}

}  // namespace

ojson parse_json_object(const std::string& text, const std::string& name) {
  ojson root;
  try {
    root = ojson::parse(text);
  } catch (const std::exception& e) {
    throw_input_error("{}: not valid JSON ({})", name, e.what());
  }
  if (!root.is_object()) throw_input_error("{}: not a JSON object", name);
  return root;
}

DisplayCalibration parse_visual_json(const std::string& text, const std::string& name) {
  return visual_json_from_object(parse_json_object(text, name), name);
}

DisplayCalibration visual_json_from_object(const ojson& root, const std::string& name) {
  if (!root.is_object()) throw_input_error("{}: not a JSON object", name);
  DisplayCalibration c;
  c.source = root;
  if (auto it = root.find("serial"); it != root.end() && it->is_string()) c.serial = *it;
  if (auto it = root.find("configVersion"); it != root.end() && it->is_string())
    c.config_version = *it;

  auto required = [&](const char* key) {
    auto v = read_number(root, key, name);
    require_field(v.has_value(), name, key, "is missing");
    return *v;
  };
  c.pitch_lpi = required("pitch");
  c.slope = required("slope");
  c.center_periods = required("center");
  c.dpi = required("DPI");
  const double w = required("screenW"), h = required("screenH");
  require_field(w == std::floor(w) && w > 0 && w < 1e6, name, "screenW",
                "must be a positive whole number of pixels");
  require_field(h == std::floor(h) && h > 0 && h < 1e6, name, "screenH",
                "must be a positive whole number of pixels");
  c.screen_w = int(w);
  c.screen_h = int(h);
  c.view_cone_deg = read_number(root, "viewCone", name).value_or(kDefaultViewConeDeg);
  c.fringe = read_number(root, "fringe", name).value_or(0.0);
  c.vertical_angle = read_number(root, "verticalAngle", name).value_or(0.0);
  c.inv_view = read_number(root, "invView", name).value_or(1.0) >= 0.5;
  c.flip_image_x = read_number(root, "flipImageX", name).value_or(0.0) >= 0.5;
  c.flip_image_y = read_number(root, "flipImageY", name).value_or(0.0) >= 0.5;
  c.flip_subp = read_number(root, "flipSubp", name).value_or(0.0) >= 0.5;
  // The Toolkit accepts both spellings; its comment calls the capital C a typo.
  const char* mode_key = root.contains("CellPatternMode") ? "CellPatternMode" : "cellPatternMode";
  c.cell_pattern_mode = read_int(root, mode_key, name, 0);

  if (auto it = root.find("subpixelCells"); it != root.end() && !it->is_null()) {
    require_field(it->is_array(), name, "subpixelCells", "is not an array");
    for (size_t i = 0; i < it->size(); ++i) {
      const ojson& cell = (*it)[i];
      require_field(cell.is_object(), name, "subpixelCells[" + std::to_string(i) + "]",
                    "is not an object");
      c.subpixel_cells.push_back({read_cell_value(cell, "ROffsetX", name, i),
                                  read_cell_value(cell, "ROffsetY", name, i),
                                  read_cell_value(cell, "GOffsetX", name, i),
                                  read_cell_value(cell, "GOffsetY", name, i),
                                  read_cell_value(cell, "BOffsetX", name, i),
                                  read_cell_value(cell, "BOffsetY", name, i)});
    }
  }
  c.check(name);
  return c;
}

DisplayCalibration read_visual_json(const std::filesystem::path& path) {
  return parse_visual_json(read_text_file(path), path.string());
}

ojson to_visual_json(const DisplayCalibration& c) {
  ojson root = c.source.is_object() ? c.source : ojson::object();
  if (!c.config_version.empty() || root.contains("configVersion"))
    root["configVersion"] = c.config_version;
  if (!c.serial.empty() || root.contains("serial")) root["serial"] = c.serial;
  put_number(root, "pitch", c.pitch_lpi);
  put_number(root, "slope", c.slope);
  put_number(root, "center", c.center_periods);
  if (root.contains("fringe") || c.fringe != 0) put_number(root, "fringe", c.fringe);
  put_number(root, "viewCone", c.view_cone_deg);
  put_number(root, "invView", c.inv_view ? 1.0 : 0.0);
  put_number(root, "verticalAngle", c.vertical_angle);
  put_number(root, "DPI", c.dpi);
  put_number(root, "screenW", c.screen_w);
  put_number(root, "screenH", c.screen_h);
  put_number(root, "flipImageX", c.flip_image_x ? 1.0 : 0.0);
  put_number(root, "flipImageY", c.flip_image_y ? 1.0 : 0.0);
  put_number(root, "flipSubp", c.flip_subp ? 1.0 : 0.0);
  const bool lower = root.contains("cellPatternMode") && !root.contains("CellPatternMode");
  if (root.contains("CellPatternMode") || root.contains("cellPatternMode") ||
      c.cell_pattern_mode != 0 || c.has_cells())
    put_number(root, lower ? "cellPatternMode" : "CellPatternMode", c.cell_pattern_mode);
  if (root.contains("subpixelCells") || c.has_cells()) {
    // Rewrite only when the cells changed, to keep the stored number forms.
    bool same = root.contains("subpixelCells") && root["subpixelCells"].is_array() &&
                root["subpixelCells"].size() == c.subpixel_cells.size();
    ojson cells = ojson::array();
    for (size_t i = 0; i < c.subpixel_cells.size(); ++i) {
      const auto& s = c.subpixel_cells[i];
      ojson cell = {{"ROffsetX", s.r_x}, {"ROffsetY", s.r_y}, {"GOffsetX", s.g_x},
                    {"GOffsetY", s.g_y}, {"BOffsetX", s.b_x}, {"BOffsetY", s.b_y}};
      if (same) {
        for (auto& [k, v] : cell.items()) {
          const ojson& old = root["subpixelCells"][i];
          if (!old.contains(k) || !old[k].is_number() || old[k].get<double>() != v.get<double>())
            same = false;
        }
      }
      cells.push_back(cell);
    }
    if (!same) root["subpixelCells"] = cells;
  }
  return root;
}

void write_visual_json(const std::filesystem::path& path, const DisplayCalibration& c) {
  write_text_atomic(path, to_visual_json(c).dump() + "\n");
}

}  // namespace lfd::display
