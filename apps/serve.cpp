// `lfd serve`: the display's open Looking Glass service (docs/serve.md). Thin: serve/ speaks the
// protocols, play/ shows on the display; this file reads the options, builds one Player per
// display, runs their frames on the main thread and stops on SIGINT/SIGTERM within a second
// (serve/stop_on_signal.hpp).
//   lfd serve --device auto
//   lfd serve --calibration calibration.json --allow-origin https://my.app.example
//   lfd serve --status
#include <chrono>
#include <iostream>
#include <memory>

#include <fmt/format.h>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "device/device_discovery.hpp"
#include "play/player.hpp"
#include "serve/player_display_service.hpp"
#include "serve/served_display.hpp"
#include "serve/service.hpp"
#include "serve/status_client.hpp"
#include "serve/stop_on_signal.hpp"
#include "util/error.hpp"

namespace lfd::apps {
namespace {

int print_status(const serve::ListenAddress& address) {
  const nlohmann::json s = serve::query_status(address);
  fmt::print("lfd serve {} at http://{}:{}/\n", s.value("version", "?"), address.url_host(), address.bridge_port);
  fmt::print("  showing   {}\n", s.value("showing", ""));
  if (!s.value("playlist", std::string()).empty())
    fmt::print("  playlist  {} (entry {} of {}, {})\n", s["playlist"].get<std::string>(), s.value("index", -1) + 1,
               s.value("entries", 0), s.value("playing", false) ? "playing" : "paused");
  for (const auto& d : s.value("displays", nlohmann::json::array()))
    fmt::print("  display {} {}: {} ({})\n", d.value("index", 0), d.value("hwid", ""), d.value("calibration", ""),
               d.value("calibration_source", ""));
  return 0;
}

std::vector<serve::ServedDisplay> displays_to_serve(const std::vector<std::string>& files, const std::string& device) {
  std::vector<display::Calibration> devices;
  if (!device.empty()) devices.push_back(device::read_device_calibration(device));
  std::vector<std::filesystem::path> paths(files.begin(), files.end());
  auto displays = serve::served_displays(paths, devices);
  if (displays.empty()) throw_input_error("--calibration or --device: no display to serve");
  return displays;
}

// The Players' frames until a signal or a window closes.
void run_players(const std::vector<std::unique_ptr<play::Player>>& players, serve::StopOnSignal& stop) {
  while (!stop.requested())
    for (auto& p : players)
      if (!p->run_frame()) stop.request();
}

}  // namespace

int RunServe(int argc, char** argv) {
  CLI::App app{"Serve the display to existing Looking Glass apps, unmodified: the HoloPlay Service protocol\n"
               "(ws://localhost:11222/driver: holoplay-core, @lookingglass/webxr, Blender) and Bridge's HTTP\n"
               "API (http://localhost:33334, events ws://localhost:9724/event_source: bridge.js), with lfd's\n"
               "calibration. Loopback only unless --listen; web pages from other origins are refused.\n"
               "Examples:\n"
               "  lfd serve --device auto\n"
               "  lfd serve --calibration calibration.json --device auto   (the file wins for its unit)\n"
               "  lfd serve --status\n"
               "  lfd serve --listen 0.0.0.0      (other machines: the console asks for lfd serve --print-token)",
               "serve"};
  std::vector<std::string> calibrations, origins;
  std::string device;
  serve::ServeOptions options;
  play::PlayerOptions player_options;
  bool status = false;
  std::size_t budget_mib = options.limits.memory_budget_bytes >> 20;
  std::string state_file = serve::default_state_file().string();
  app.add_option("--calibration", calibrations, "a display: lfd calibration.json or visual.json (repeat for several)")
      ->check(CLI::ExistingFile);
  app.add_option("--device", device, "a connected Looking Glass unit's factory calibration: auto or a serial");
  app.add_option("--allow-origin", origins, "also let web pages from this origin in (repeat)");
  app.add_option("--listen", options.listen.host, "the address to listen on (other machines can reach a non-loopback one)")
      ->capture_default_str();
  app.add_option("--state-file", state_file, "where playlists are kept")->capture_default_str();
  app.add_option("--monitor", player_options.monitor_prefix, "the displays' monitor name prefix")->capture_default_str();
  app.add_flag("--simulated", player_options.simulated_display, "show each display in a window (no display connected)");
  app.add_option("--memory-budget", budget_mib,
                 "MiB the service may keep resident in all: requests whose content would exceed it are answered busy")
      ->capture_default_str()
      ->check(CLI::Range(64, 1 << 20));
  std::string content = serve::default_content_folder().string();
  app.add_option("--content", content, "the console's content folder (uploads land here)")->capture_default_str();
  std::size_t upload_mib = options.limits.max_upload_bytes >> 20;
  app.add_option("--max-upload", upload_mib, "MiB a file uploaded to the console may have")
      ->capture_default_str()
      ->check(CLI::Range(1, 4096));
  bool print_token = false;
  app.add_flag("--print-token", print_token,
               "print the access token a service listening beyond loopback (--listen) needs, then exit");
  app.add_flag("--status", status, "ask the running service what it shows, then exit");
  std::string gl = "auto";
  add_gl_option(app, gl);
  if (auto code = parse(app, argc, argv)) return *code;
  player_options.gl = gl_request(gl);
  if (status) return print_status(options.listen);
  // The token lives beside the state file, 0600 (serve/access_token.hpp, docs/console.md).
  const auto token_file = serve::token_file_beside(state_file);
  if (print_token) {
    fmt::print("{}\n", serve::AccessToken::load_or_create(token_file).text());
    return 0;
  }
  if (!options.listen.is_loopback()) options.access_token = serve::AccessToken::load_or_create(token_file);
  options.content_folder = content;
  options.limits.max_upload_bytes = upload_mib << 20;

  // From the first signal on, at most a second until the process ends (stop_on_signal.hpp).
  serve::StopOnSignal stop(std::chrono::milliseconds(1000));
  serve::return_large_buffers_to_the_system();
  options.limits.memory_budget_bytes = budget_mib << 20;
  options.allowed_origins = origins;
  options.state_file = state_file;
  const auto displays = displays_to_serve(calibrations, device);
  std::vector<std::unique_ptr<play::Player>> players;
  std::vector<play::Player*> raw;
  for (const auto& d : displays) {
    play::PlayerOptions o = player_options;
    o.calibration = d.calibration;
    o.display_name = d.calibration_path.string();
    o.print_notices = true;
    players.push_back(std::make_unique<play::Player>(o));
    raw.push_back(players.back().get());
  }
  // The budget counts the process as it stands with its windows open and drawn once (GL and its
  // shaders, libraries, threads) and 32 MiB for the stacks and connection buffers to come;
  // requests get the rest.
  for (auto& p : players) p->run_frame();
  serve::MemoryBudget budget(options.limits.memory_budget_bytes);
  const std::size_t baseline = serve::resident_bytes() + (32u << 20);
  budget.set_aside(baseline, "lfd serve itself");
  budget.limit_resident(options.limits.memory_budget_bytes);
  serve::PlayerDisplayService display_service(raw, displays, budget);
  serve::Service service(display_service, options, &budget);
  service.start();
  for (const auto& line : service.describe()) std::cerr << "lfd serve: " << line << "\n";
  for (const auto& d : displays)
    std::cerr << fmt::format("lfd serve: display {} {}: {} ({}), default quilt {}x{} ({} views) on {}\n", d.index,
                             d.hwid, d.calibration_path.string(), d.calibration_source, d.default_quilt.cols,
                             d.default_quilt.rows, d.default_quilt.views,
                             raw[d.index]->state().on_display ? "its monitor" : "a simulated display window");
  std::cerr << fmt::format("lfd serve: memory budget {} MiB, {} MiB of it the service itself\n", budget_mib,
                           baseline >> 20);
  run_players(players, stop);
  std::cerr << "lfd serve: stopping\n";
  service.stop();
  return 0;
}

}  // namespace lfd::apps
