// The vendor clients' settings files (docs/bridge-inproc.md "How clients find it").
#include "bridge_inproc/bridge_registration.hpp"

#include <cstdlib>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

#ifndef LFD_BRIDGE_INSTALLED_DIR_FROM_BIN
#define LFD_BRIDGE_INSTALLED_DIR_FROM_BIN "../lib/lfd"
#endif

namespace lfd::bridge {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

constexpr const char* kLibraryFile = "libbridge_inproc.so";

bool is_lfd_folder(const std::string& path) {
  return fs::path(path).filename().string().rfind("lfd-bridge-", 0) == 0;
}

bool is_lfd_entry(const json& entry) {
  if (entry.contains("installer") && entry["installer"] == "lfd") return true;
  return entry.contains("path") && entry["path"].is_string() && is_lfd_folder(entry["path"].get<std::string>());
}

// The settings object of `path` ({} when absent); InputError when it is not a JSON object whose
// install_locations, if present, is an array.
json read_settings(const fs::path& path) {
  if (!fs::exists(path)) return json::object();
  const std::string text = read_text_file(path);
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    throw_input_error("{}: not JSON ({}); left as it is", path.string(), e.what());
  }
  if (!root.is_object()) throw_input_error("{}: not a JSON object; left as it is", path.string());
  if (root.contains("install_locations") && !root["install_locations"].is_array())
    throw_input_error("{}: install_locations: not an array; left as it is", path.string());
  return root;
}

void add_entry(const fs::path& path, const fs::path& library_dir) {
  json root = read_settings(path);
  json kept = json::array();
  if (root.contains("install_locations"))
    for (const json& entry : root["install_locations"])
      if (!is_lfd_entry(entry)) kept.push_back(entry);
  kept.push_back({{"version", bridge_version_text()}, {"path", library_dir.string()}, {"installer", "lfd"}});
  root["install_locations"] = kept;
  write_text_atomic(path, root.dump(4) + "\n");
}

int remove_entries(const fs::path& path) {
  if (!fs::exists(path)) return 0;
  json root = read_settings(path);
  if (!root.contains("install_locations")) return 0;
  json kept = json::array();
  int removed = 0;
  for (const json& entry : root["install_locations"]) {
    if (is_lfd_entry(entry))
      ++removed;
    else
      kept.push_back(entry);
  }
  if (removed == 0) return 0;
  root["install_locations"] = kept;
  write_text_atomic(path, root.dump(4) + "\n");
  return removed;
}

std::vector<std::string> read_lines(const fs::path& path) {
  std::vector<std::string> lines;
  if (!fs::exists(path)) return lines;
  std::istringstream in(read_text_file(path));
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

void write_lines(const fs::path& path, const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  write_text_atomic(path, text);
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

std::string bridge_version_text() { return fmt::format("{}.{}.{}", kBridgeMajor, kBridgeMinor, kBridgeBuild); }

std::string library_folder_name() { return "lfd-bridge-" + bridge_version_text(); }

RegistrationFiles registration_files(const fs::path& home) {
  return {home / ".config" / "LookingGlass" / "Bridge" / "settings.json", home / ".lgf" / "bridge_install_locations",
          home / ".lgf" / "Bridge" / "settings.json"};
}

RegistrationFiles registration_files() {
  const char* home = std::getenv("HOME");
  if (!home || !*home) throw_input_error("HOME is not set: the Bridge settings files live under it");
  return registration_files(home);
}

void register_library(const RegistrationFiles& files, const fs::path& library_dir) {
  if (!fs::exists(library_dir / kLibraryFile))
    throw_input_error("{}: no {} there", library_dir.string(), kLibraryFile);
  if (!is_lfd_folder(library_dir.string()))
    throw_input_error("{}: the folder must be called lfd-bridge-<version> (the legacy list reads the version "
                      "from its name)", library_dir.string());
  // Read all three first: one that is not ours to parse stops the command before any is changed.
  read_settings(files.python_settings);
  read_settings(files.native_settings);
  add_entry(files.python_settings, library_dir);
  add_entry(files.native_settings, library_dir);
  std::vector<std::string> lines;
  for (const std::string& line : read_lines(files.legacy_list))
    if (!is_lfd_folder(trimmed(line))) lines.push_back(line);
  lines.push_back(library_dir.string());
  write_lines(files.legacy_list, lines);
}

int unregister_library(const RegistrationFiles& files) {
  int removed = remove_entries(files.python_settings) + remove_entries(files.native_settings);
  std::vector<std::string> lines;
  int legacy = 0;
  for (const std::string& line : read_lines(files.legacy_list)) {
    if (is_lfd_folder(trimmed(line)))
      ++legacy;
    else
      lines.push_back(line);
  }
  if (legacy > 0) write_lines(files.legacy_list, lines);
  return removed + legacy;
}

std::vector<RegisteredEntry> registered_entries(const RegistrationFiles& files) {
  std::vector<RegisteredEntry> out;
  for (const fs::path& path : {files.python_settings, files.native_settings}) {
    const json root = read_settings(path);
    if (!root.contains("install_locations")) continue;
    for (const json& entry : root["install_locations"]) {
      RegisteredEntry e;
      e.file = path.string();
      if (entry.contains("version") && entry["version"].is_string()) e.version = entry["version"].get<std::string>();
      if (entry.contains("path") && entry["path"].is_string()) e.path = entry["path"].get<std::string>();
      e.lfd = is_lfd_entry(entry);
      e.library_present = !e.path.empty() && fs::exists(fs::path(e.path) / kLibraryFile);
      out.push_back(e);
    }
  }
  for (const std::string& line : read_lines(files.legacy_list)) {
    const std::string path = trimmed(line);
    if (path.empty()) continue;
    RegisteredEntry e;
    e.file = files.legacy_list.string();
    e.path = path;
    e.lfd = is_lfd_folder(path);
    e.library_present = fs::exists(fs::path(path) / kLibraryFile);
    out.push_back(e);
  }
  return out;
}

fs::path default_library_dir(const fs::path& exe) {
  const fs::path bin = exe.parent_path();
  const std::vector<fs::path> candidates = {
      bin.parent_path() / "bridge_inproc" / library_folder_name(),  // the build tree: build/apps/lfd
      bin / LFD_BRIDGE_INSTALLED_DIR_FROM_BIN / library_folder_name(),
  };
  for (const fs::path& c : candidates)
    if (fs::exists(c / kLibraryFile)) return fs::weakly_canonical(c);
  throw_input_error("no {} beside the program (looked in {} and {}); pass --library DIR", kLibraryFile,
                    candidates[0].string(), candidates[1].string());
}

}  // namespace lfd::bridge
