#pragma once
// What the viewer's controls set, and the small per-display config file that remembers them
// (~/.config/lfd/viewer/<display>.json): a display owner tunes N_chunk, the focal distance or the
// depthiness once for their unit and the next `lfd view` starts there.
#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "render/g2lf.hpp"

namespace lfd::viewer {

// kG2lfDirect: G2LF's planes straight into the panel, no quilt (gpu/panel/gl_direct_panel.hpp).
enum class Method { kG2lf, kPerView, kG2lfDirect };

struct ViewerSettings {
  Method method = Method::kG2lf;
  render::G2lfOptions g2lf;       // N_chunk, P_s, filter, binning, precision, D_shift
  int views = 0;                  // 0: the display's recommendation
  float view_cone_deg = 0.0f;     // 0: the display's (measured) cone
  // Zero-parallax plane as a fraction of the camera-to-target distance (1: at the target).
  float focal_fraction = 1.0f;
  // Scales the view cone the quilt is rendered with: < 1 flattens the scene, > 1 deepens it.
  float depthiness = 1.0f;
  glm::vec3 background{0.0f};
  int view_height_px = 512;

  // Throws InputError "<source>: <field>: <problem>" for values out of range.
  void check(const std::string& source) const;
};

std::string method_name(Method m);  // "g2lf" | "per-view" | "g2lf-direct"
Method parse_method(const std::string& name);  // InputError for another name

// JSON text of the settings, and back (missing fields keep their defaults; wrong types and
// out-of-range values are InputErrors naming `source` and the field).
std::string settings_to_json(const ViewerSettings& s);
ViewerSettings settings_from_json(const std::string& text, const std::string& source);

// Where the settings of one display live: $XDG_CONFIG_HOME (else ~/.config)/lfd/viewer/<key>.json,
// the key made of letters, digits, '-' and '_' from the display's serial or name.
std::filesystem::path settings_path_for_display(const std::string& display_key);
// The saved settings, or `defaults` when there is no file. A malformed file is an InputError.
ViewerSettings load_settings(const std::filesystem::path& path, const ViewerSettings& defaults);
// Written atomically.
void save_settings(const std::filesystem::path& path, const ViewerSettings& s);

}  // namespace lfd::viewer
