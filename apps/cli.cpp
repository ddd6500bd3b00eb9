#include "apps/cli.hpp"

#include <cmath>
#include <iostream>

#include "device/device_discovery.hpp"
#include "util/error.hpp"

namespace lfd::apps {

std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::CallForAllHelp& e) {
    std::cout << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::ParseError& e) {
    std::cerr << "lfd " << app.get_name() << ": " << e.what() << " (see --help)\n";
    return 2;
  }
  return std::nullopt;
}

std::vector<double> parse_numbers(const std::string& text, char sep, size_t count,
                                  const std::string& option) {
  std::vector<double> values;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = text.find(sep, start);
    const std::string part = text.substr(start, end == std::string::npos ? std::string::npos
                                                                          : end - start);
    try {
      size_t used = 0;
      const double v = std::stod(part, &used);
      if (used != part.size() || !std::isfinite(v)) throw std::invalid_argument(part);
      values.push_back(v);
    } catch (const std::exception&) {
      throw_input_error("{}: '{}' is not a list of {} numbers separated by '{}'", option, text,
                        count, sep);
    }
    if (end == std::string::npos) break;
    start = end + 1;
  }
  if (values.size() != count)
    throw_input_error("{}: '{}' has {} values, expected {}", option, text, values.size(), count);
  return values;
}

display::ViewSize parse_view_size(const std::string& text, const std::string& option, bool square,
                                  int max_side) {
  const bool one = square && text.find('x') == std::string::npos;
  const auto wh = parse_numbers(text, 'x', one ? 1 : 2, option);
  const double w = wh[0], h = one ? wh[0] : wh[1];
  if (w < 1 || h < 1 || w > max_side || h > max_side || w != int(w) || h != int(h))
    throw_input_error("{}: '{}' must be {} in [1, {}]", option, text, square ? "N or WxH, integers" : "two integers",
                      max_side);
  return display::ViewSize{int(w), int(h)};
}

void DisplaySource::add(CLI::App& app, const std::string& file_flag, const std::string& file_help,
                        bool required) {
  file_flag_ = file_flag;
  file_option = app.add_option(file_flag, file, file_help + (required ? " (or --device)" : ""));
  device_option = app.add_option(
      "--device", device,
      "read the display's calibration from an attached Looking Glass: auto (the only one) or "
      "its serial (lfd device list)");
  file_option->excludes(device_option);
  if (required) {
    // Given --device, the file is not required: cleared while parsing, before CLI11 checks.
    file_option->required();
    CLI::Option* file_opt = file_option;
    device_option->trigger_on_parse()->each([file_opt](const std::string&) { file_opt->required(false); });
  }
  app.add_option("--root", root, "--device: search paths (mount table, /media, /sys) under DIR")
      ->needs(device_option);
}

display::Calibration DisplaySource::load() {
  if (!file.empty()) {
    name_ = file;
    return display::read_calibration(file);
  }
  if (device.empty()) throw_input_error("{} or --device: one is required", file_flag_);
  device::DiscoveryOptions options;
  options.root = root;
  const device::Discovery found = device::discover_devices(options);
  const device::FoundDevice& unit = device::select_device(found, device);
  name_ = "device " + (unit.serial.empty() ? unit.source : unit.serial);
  std::cerr << "using the calibration of " << unit.describe() << "\n";
  return device::calibration_of(unit);
}

int run_subcommand(const std::string& command, const std::string& usage, std::span<const Subcommand> table,
                   int argc, char** argv) {
  const std::string sub = argc > 1 ? argv[1] : "";
  for (const Subcommand& s : table)
    if (sub == s.name) return s.run(argc - 1, argv + 1);
  if (sub == "--help" || sub == "-h") {
    std::cout << usage;
    return 0;
  }
  if (sub.empty()) {
    std::cerr << usage;
    return 2;
  }
  std::string names;
  for (const Subcommand& s : table) names += (names.empty() ? "" : ", ") + std::string(s.name);
  std::cerr << command << ": unknown subcommand '" << sub << "' (" << names << "; see " << command << " --help)\n";
  return 2;
}

}  // namespace lfd::apps
