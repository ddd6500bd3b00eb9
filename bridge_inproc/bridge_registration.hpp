#pragma once
// Where the vendor's clients look for libbridge_inproc (docs/bridge-inproc.md "How clients find
// it"): the Bridge Python SDK reads ~/.config/LookingGlass/Bridge/settings.json and the legacy
// list ~/.lgf/bridge_install_locations (one folder per line, its version taken from the folder's
// name); the native samples' Controller reads ~/.lgf/Bridge/settings.json. Both JSON files hold
// {"install_locations": [{"version": "2.6.2", "path": FOLDER}, ...]} and the clients load
// FOLDER/libbridge_inproc.so. lfd adds its entry (marked "installer": "lfd"), keeps every other
// entry and key, and replaces each file atomically.
#include <filesystem>
#include <string>
#include <vector>

namespace lfd::bridge {

// The Bridge version lfd's library reports (get_bridge_version) and registers: the native
// samples' header asks for 2.6.2, the Python SDK takes 2.6.0 or later of major 2.
inline constexpr int kBridgeMajor = 2, kBridgeMinor = 6, kBridgeBuild = 2;
std::string bridge_version_text();  // "2.6.2"
// The library's folder name: the legacy list reads the version from it.
std::string library_folder_name();  // "lfd-bridge-2.6.2"

struct RegistrationFiles {
  std::filesystem::path python_settings;  // ~/.config/LookingGlass/Bridge/settings.json
  std::filesystem::path legacy_list;      // ~/.lgf/bridge_install_locations
  std::filesystem::path native_settings;  // ~/.lgf/Bridge/settings.json
};
RegistrationFiles registration_files(const std::filesystem::path& home);
// $HOME's.
RegistrationFiles registration_files();

// Adds (or refreshes) lfd's entry for `library_dir` in the three files. InputError naming the
// file when one exists but is not JSON with an install_locations array (it is left as it is).
void register_library(const RegistrationFiles& files, const std::filesystem::path& library_dir);
// Removes lfd's entries only (those marked "installer": "lfd", and legacy lines naming a folder
// called lfd-bridge-*); returns how many went.
int unregister_library(const RegistrationFiles& files);

struct RegisteredEntry {
  std::string file;  // which settings file
  std::string version, path;
  bool lfd = false;  // lfd's own entry
  bool library_present = false;  // path/libbridge_inproc.so exists
};
// Every entry of the three files, lfd's and others'.
std::vector<RegisteredEntry> registered_entries(const RegistrationFiles& files);

// The folder holding the libbridge_inproc.so built or installed with the program at `exe`
// (build tree: <build>/bridge_inproc/lfd-bridge-2.6.2; installed: <prefix>/lib/<arch>/lfd/...);
// InputError saying where it looked when neither exists.
std::filesystem::path default_library_dir(const std::filesystem::path& exe);

}  // namespace lfd::bridge
