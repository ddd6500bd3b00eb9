// lfd bridge: lets the vendor's Bridge SDK clients find lfd's libbridge_inproc
// (docs/bridge-inproc.md "How clients find it"). Thin: bridge_inproc/ does the work.
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "bridge_inproc/bridge_registration.hpp"
#include "bridge_inproc/bridge_settings.hpp"
#include "display/calibration_file.hpp"
#include "util/error.hpp"

namespace lfd::apps {

namespace {

namespace fs = std::filesystem;

int RunBridgeRegister(int argc, char** argv) {
  CLI::App app{"Register lfd's libbridge_inproc where the vendor's clients look for Bridge (the Python SDK: "
               "~/.config/LookingGlass/Bridge/settings.json and ~/.lgf/bridge_install_locations; the native "
               "samples: ~/.lgf/Bridge/settings.json), keeping every entry already there, and say which "
               "display it drives (~/.config/lfd/bridge.json, or $LFD_BRIDGE_CONFIG).\n"
               "\nExamples:\n"
               "  lfd bridge register --device auto\n"
               "  lfd bridge register --calibration visual.json --monitor HDMI-1\n"
               "  lfd bridge register --device auto --gl es      # OpenGL ES 3.1 (a Raspberry Pi; docs/arm.md)\n"
               "  lfd bridge register --calibration calibration.json --library /opt/lfd/lib/lfd/lfd-bridge-2.6.2",
               "bridge register"};
  std::string calibration, device, monitor = "LKG", library, gl;
  auto* file_option = app.add_option("--calibration", calibration, "calibration.json or visual.json of the display");
  app.add_option("--device", device, "an attached Looking Glass: auto or its serial (the default: auto)")
      ->excludes(file_option);
  app.add_option("--monitor", monitor, "start of the display's monitor name")->capture_default_str();
  app.add_option("--library", library, "the folder holding libbridge_inproc.so (default: the one built or "
                                       "installed with this program)");
  add_gl_option(app, gl);  // the library's own contexts; LFD_GL in a client's environment overrides it
  if (auto code = parse(app, argc, argv)) return *code;

  bridge::LfdBridgeSettings settings;
  settings.monitor = monitor;
  settings.gl = gl;
  if (!calibration.empty()) {
    display::read_calibration(calibration);  // a file that cannot be read is refused now
    settings.calibrations.push_back(fs::absolute(calibration).string());
    settings.device = "";
  } else {
    settings.device = device.empty() ? "auto" : device;
  }
  const fs::path library_dir =
      library.empty() ? bridge::default_library_dir(fs::read_symlink("/proc/self/exe")) : fs::absolute(library);
  const bridge::RegistrationFiles files = bridge::registration_files();
  bridge::register_library(files, library_dir);
  const fs::path settings_path = bridge::lfd_settings_path();
  bridge::write_lfd_settings(settings_path, settings);
  fmt::print("registered {} as Bridge {}\n  in {}\n  in {}\n  in {}\ndisplay: {}, gl {} (settings {})\n",
             library_dir.string(), bridge::bridge_version_text(), files.python_settings.string(),
             files.legacy_list.string(), files.native_settings.string(),
             calibration.empty() ? "device " + settings.device : settings.calibrations.front(), settings.gl,
             settings_path.string());
  return 0;
}

int RunBridgeUnregister(int argc, char** argv) {
  CLI::App app{"Remove lfd's entries from the Bridge settings files (other entries stay) and lfd's bridge "
               "settings.\n\nExample:\n  lfd bridge unregister",
               "bridge unregister"};
  if (auto code = parse(app, argc, argv)) return *code;
  const int removed = bridge::unregister_library(bridge::registration_files());
  const fs::path settings_path = bridge::lfd_settings_path();
  std::error_code ignored;
  fs::remove(settings_path, ignored);
  fmt::print("removed {} lfd entr{} from the Bridge settings files\n", removed, removed == 1 ? "y" : "ies");
  return 0;
}

int RunBridgeStatus(int argc, char** argv) {
  CLI::App app{"What the Bridge settings files list (lfd's entries and others'), and what lfd's library "
               "drives.\n\nExamples:\n  lfd bridge status\n  lfd bridge status --json",
               "bridge status"};
  bool json = false;
  app.add_flag("--json", json, "machine-readable output");
  if (auto code = parse(app, argc, argv)) return *code;
  const std::vector<bridge::RegisteredEntry> entries = bridge::registered_entries(bridge::registration_files());
  const fs::path settings_path = bridge::lfd_settings_path();
  const bridge::LfdBridgeSettings settings = bridge::read_lfd_settings(settings_path);
  bool registered = false;
  for (const auto& e : entries) registered |= e.lfd;
  if (json) {
    nlohmann::ordered_json j;
    j["registered"] = registered;
    j["entries"] = nlohmann::ordered_json::array();
    for (const auto& e : entries)
      j["entries"].push_back({{"file", e.file}, {"version", e.version}, {"path", e.path}, {"lfd", e.lfd},
                              {"library_present", e.library_present}});
    j["settings"] = {{"file", settings_path.string()}, {"calibrations", settings.calibrations},
                     {"device", settings.device}, {"monitor", settings.monitor}, {"gl", settings.gl}};
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  fmt::print("lfd's libbridge_inproc is {}registered\n", registered ? "" : "not ");
  for (const auto& e : entries)
    fmt::print("  {} {} {}{}  ({})\n", e.lfd ? "lfd   " : "other ", e.version.empty() ? "-" : e.version, e.path,
               e.library_present ? "" : " [no libbridge_inproc.so there]", e.file);
  std::vector<std::string> shown = settings.calibrations;
  if (!settings.device.empty()) shown.push_back("device " + settings.device);
  fmt::print("displays: {}; gl {}  (settings {})\n", fmt::join(shown, ", "), settings.gl, settings_path.string());
  return 0;
}

}  // namespace

int RunBridge(int argc, char** argv) {
  const std::string usage =
      "Bridge SDK clients on lfd (docs/bridge-inproc.md): lfd's libbridge_inproc where the vendor's\n"
      "Python SDK and native samples look for Bridge.\n"
      "\nUsage:\n"
      "  lfd bridge register [--calibration C.json | --device auto] [--monitor NAME] [--gl auto|desktop|es] [--library DIR]\n"
      "  lfd bridge unregister\n"
      "  lfd bridge status [--json]\n";
  static constexpr Subcommand kSubcommands[] = {{"register", RunBridgeRegister}, {"unregister", RunBridgeUnregister}, {"status", RunBridgeStatus}};
  return run_subcommand("lfd bridge", usage, kSubcommands, argc, argv);
}

}  // namespace lfd::apps
