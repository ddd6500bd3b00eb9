#pragma once
// How an RGB-D image or video frame (colour and depth side by side) is read and turned into views:
// the Looking Glass conventions of bridge.js (@lookingglass/bridge 0.0.8, its RGBDHologram settings
// and src/library/schemas/defaults.ts), with bridge.js's names, numbering, ranges and defaults
// (docs/rgbd.md "Options"). Bridge's own renderer is closed: what each value does to the views is
// lfd's model, written out in docs/rgbd.md "The view model".
#include <string>
#include <utility>
#include <vector>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace lfd::rgbd {

// Where the depth half sits, numbered as bridge.js's schema (0 top, 1 bottom, 2 right, 3 left);
// bridge.h and the Python SDK number them differently (docs/rgbd.md "Options").
enum class DepthLocation { top = 0, bottom = 1, right = 2, left = 3 };

// The bridge.js ranges (schemas/defaults.ts) and defaults (RGBDHologram / RGBDPlaylistItem).
inline constexpr double kMinDepthiness = 0.1, kMaxDepthiness = 4.0, kDefaultDepthiness = 1.5;
inline constexpr double kMinFocus = -0.05, kMaxFocus = 0.05;
inline constexpr double kMinZoom = 0.1, kMaxZoom = 4.0;
inline constexpr double kMinCropPos = -2.0, kMaxCropPos = 2.0;
// depth_cutoff: bridge.js 0.0.8-alpha.4 sends a 0/1 flag, 0.0.8-alpha.6 a threshold in [0, 1]
// with default 0 (bridge.h: "a z-depth threshold value"); docs/rgbd.md "Depth cutoff".
inline constexpr double kMinDepthCutoff = 0.0, kMaxDepthCutoff = 1.0;

struct RgbdOptions {
  DepthLocation depth_loc = DepthLocation::right;  // colour left, depth right
  double depthiness = kDefaultDepthiness;          // scales the relief (all parallax)
  double focus = 0.0;            // the zero-parallax depth's offset (docs/rgbd.md)
  bool depth_inversion = false;  // false: white (1) is near; true: black is near
  bool chroma_depth = false;     // depth as hue (red near, blue far) instead of grey
  double zoom = 1.0;             // magnification of the colour/depth about the crop centre
  double crop_pos_x = 0.0;       // crop centre offset, in half image widths (+ right)
  double crop_pos_y = 0.0;       // in half image heights (+ up)
  double depth_cutoff = 0.0;     // depths d < depth_cutoff (1 = near) are removed: drawn black

  // Throws lfd::InputError "<what>: <field> ..." naming the bridge.js field when a value is
  // outside bridge.js's range or not finite.
  void check(const std::string& what = "RGB-D options") const;
};

// "top", "bottom", "right", "left" (any case) or bridge.js's number "0".."3". Throws
// InputError naming `depth_loc` otherwise.
DepthLocation parse_depth_location(std::string_view text);
std::string depth_location_name(DepthLocation location);

// Sets one option from its bridge.js key (`depth_loc`, `depthiness`, `focus`, `depth_inversion`,
// `chroma_depth`, `zoom`, `crop_pos_x`, `crop_pos_y`, `depth_cutoff`) and a command-line string ("1", "true",
// "right", "0.02"); the dashed spelling (`depth-loc`) is accepted too. Throws InputError
// naming the key for an unknown key or a value that does not parse or is out of range.
void set_rgbd_option(RgbdOptions& options, std::string_view key, std::string_view value);

// Reads the RGB-D keys of a bridge.js RGBDHologram settings object or playlist entry (other keys
// such as uri, aspect or durationMS are left to the caller) over `base`; bridge.js's 0/1 flags
// and JSON booleans both work (depth_cutoff: a number in [0, 1] or a boolean). Throws InputError naming the key on a wrong type or range.
RgbdOptions rgbd_options_from_json(const nlohmann::json& settings, RgbdOptions base = {});
// The same from JSON text; InputError "RGB-D settings: ..." when it is not a JSON object.
RgbdOptions parse_rgbd_options_json(std::string_view text, RgbdOptions base = {});
// The options as bridge.js keys (depth_loc as its number, flags as 0/1).
nlohmann::json rgbd_options_to_json(const RgbdOptions& options);

// The options of a command line (`lfd play`, `lfd rgbd-quilt`): a bridge.js settings file first
// (when `settings_path` is not empty; at most 1 MiB), then each flag given (key, value; an empty
// value is a flag not given). InputError naming the file or the key.
RgbdOptions rgbd_options_from_command_line(const std::string& settings_path,
                                           const std::vector<std::pair<std::string, std::string>>& flags);

}  // namespace lfd::rgbd
