#pragma once
// lfd's own settings for the library (docs/bridge-inproc.md "Which displays"): which calibration
// files and which attached unit it drives, and the monitor it looks for. `lfd bridge register`
// writes them; initialize_bridge reads them. The file is $LFD_BRIDGE_CONFIG, else
// ~/.config/lfd/bridge.json:
//   {"calibrations": ["/abs/C.json", ...], "device": "auto" | "SERIAL" | "", "monitor": "LKG",
//    "gl": "auto" | "desktop" | "es"}
// Absent, the library drives what device discovery finds ("device": "auto"). "gl" is the OpenGL
// its own contexts speak (docs/arm.md): LFD_GL, when set, overrides it.
#include <filesystem>
#include <string>
#include <vector>

#include "gpu/gl/gl_flavour.hpp"

namespace lfd::bridge {

struct LfdBridgeSettings {
  std::vector<std::string> calibrations;  // calibration.json or visual.json files
  std::string device = "auto";            // device discovery: "auto", a serial, "" for none
  std::string monitor = "LKG";            // the monitor name prefix a display's window looks for
  std::string gl = "auto";                // gpu::GlRequest's name: auto, desktop or es
};

// $LFD_BRIDGE_CONFIG, else $HOME/.config/lfd/bridge.json.
std::filesystem::path lfd_settings_path();
// The settings in `path` (the defaults when it does not exist). InputError naming the file and
// field for bad JSON or a field of the wrong type.
LfdBridgeSettings read_lfd_settings(const std::filesystem::path& path);
LfdBridgeSettings parse_lfd_settings(const std::string& text, const std::string& name);
// The OpenGL the library's contexts ask for: LFD_GL when set (InputError naming LFD_GL when bad),
// else settings.gl.
gpu::GlRequest library_gl_request(const LfdBridgeSettings& settings);
// Atomic write.
void write_lfd_settings(const std::filesystem::path& path, const LfdBridgeSettings& settings);

}  // namespace lfd::bridge
