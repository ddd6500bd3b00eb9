// lfd device: the Looking Glass units attached to this machine and their factory calibration
// (docs/devices.md). Thin: device/ does the work.
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "device/device_discovery.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::apps {

namespace {

int RunDeviceList(int argc, char** argv) {
  CLI::App app{"List the Looking Glass units this machine sees: Gen1 units on USB HID (their "
               "calibration EEPROM is read) and later units' USB volumes with "
               "LKG_calibration/visual.json. For each: kind, serial, where its calibration comes "
               "from, readable or why not, and its monitor when one matches.\n"
               "Exits with 2 when none is found.\n"
               "\nExamples:\n"
               "  lfd device list\n"
               "  lfd device list --json\n"
               "  lfd device list --root /mnt/chroot",
               "device list"};
  bool json = false;
  device::DiscoveryOptions options;
  std::string root = "/";
  app.add_flag("--json", json, "machine-readable output");
  app.add_option("--root", root, "search paths (mount table, /media, /sys) under DIR instead of /");
  app.add_option("--monitor", options.monitor_prefix,
                 "start of the display's monitor name (EDID)")->capture_default_str();
  if (auto code = parse(app, argc, argv)) return *code;
  options.root = root;

  const device::Discovery found = device::discover_devices(options);
  if (json) {
    nlohmann::ordered_json j;
    j["devices"] = nlohmann::ordered_json::array();
    for (const device::FoundDevice& d : found.devices) {
      nlohmann::ordered_json e;
      e["kind"] = d.kind == device::DeviceKind::kGen1Hid ? "gen1-hid" : "usb-volume";
      e["serial"] = d.serial;
      e["source"] = d.source;
      e["readable"] = d.readable();
      if (!d.readable()) e["problem"] = d.problem;
      if (d.readable()) e["panel"] = {{"width_px", d.screen_w}, {"height_px", d.screen_h}};
      if (!d.monitor.empty()) e["monitor"] = d.monitor;
      if (!d.monitor_problem.empty()) e["monitor_problem"] = d.monitor_problem;
      j["devices"].push_back(e);
    }
    j["notes"] = found.notes;
    std::cout << j.dump(2) << "\n";
  } else if (!found.devices.empty()) {
    fmt::print("{} Looking Glass unit{} found:\n", found.devices.size(),
               found.devices.size() == 1 ? "" : "s");
    for (const device::FoundDevice& d : found.devices) {
      fmt::print("  {}\n", d.describe());
      if (d.readable())
        fmt::print("    calibration  readable, panel {}x{}\n", d.screen_w, d.screen_h);
      else
        fmt::print("    calibration  not readable: {}\n", d.problem);
      if (!d.monitor.empty()) fmt::print("    monitor      {}\n", d.monitor);
      if (!d.monitor_problem.empty()) fmt::print("    monitor      none: {}\n", d.monitor_problem);
    }
    for (const std::string& note : found.notes) fmt::print("  note: {}\n", note);
  }
  if (found.devices.empty()) throw InputError(device::nothing_found_message(found));
  return 0;
}

int RunDeviceRead(int argc, char** argv) {
  CLI::App app{"Read a Looking Glass unit's factory calibration and write it as calibration.json "
               "(and, with --visual-json, the device's visual.json byte for byte). Nothing is "
               "written when the read fails.\n"
               "\nExamples:\n"
               "  lfd device read --out calibration.json\n"
               "  lfd device read --serial LKG-2K-04409 --out cal.json --visual-json visual.json",
               "device read"};
  std::string serial = "auto", out_path, visual_path, root = "/";
  bool force = false;
  app.add_option("--serial,--device", serial,
                 "the unit's serial (see lfd device list); auto: the only one attached")
      ->capture_default_str();
  app.add_option("--out", out_path, "calibration.json to write")->required();
  app.add_option("--visual-json", visual_path, "also write the visual.json as the device holds it");
  app.add_option("--root", root, "search paths (mount table, /media, /sys) under DIR instead of /");
  app.add_flag("--force", force, "replace existing outputs (a .bak is kept)");
  if (auto code = parse(app, argc, argv)) return *code;

  device::DiscoveryOptions options;
  options.root = root;
  const device::Discovery found = device::discover_devices(options);
  const device::FoundDevice& unit = device::select_device(found, serial);
  const display::Calibration calibration = device::calibration_of(unit);
  // Every check before the first write, so a refusal leaves nothing behind.
  for (const std::string& path : {out_path, visual_path})
    if (!force && !path.empty() && std::filesystem::exists(path))
      throw_input_error("{}: already exists (use --force to replace it; a .bak copy is kept)", path);
  display::write_calibration(out_path, calibration, force);
  if (!visual_path.empty()) {
    guard_overwrite(visual_path, force);
    write_text_atomic(visual_path, unit.visual_json);
  }
  fmt::print("{}: wrote {}{}\n", unit.describe(), out_path,
             visual_path.empty() ? std::string() : " and " + visual_path);
  return 0;
}

}  // namespace

int RunDevice(int argc, char** argv) {
  const std::string usage =
      "Looking Glass devices: find them and read their factory calibration (docs/devices.md).\n"
      "\nUsage:\n"
      "  lfd device list [--json] [--root DIR]\n"
      "  lfd device read [--serial S] --out calibration.json [--visual-json visual.json]\n"
      "\nOther commands take --device auto|SERIAL in place of --calibration FILE.\n";
  static constexpr Subcommand kSubcommands[] = {{"list", RunDeviceList}, {"read", RunDeviceRead}};
  return run_subcommand("lfd device", usage, kSubcommands, argc, argv);
}

}  // namespace lfd::apps
