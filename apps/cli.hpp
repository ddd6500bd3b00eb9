#pragma once
// Shared command-line plumbing: parsing with CLI11 and the exit-code convention
// (0 success or --help, 2 bad usage/input, 1 other failures).
#include <optional>
#include <span>
#include <string>

#include <CLI/CLI.hpp>

#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"

namespace lfd::apps {

// Parses argv into `app`. Returns an exit code to return immediately (help printed: 0,
// bad usage: 2 after a one-line message), or nullopt to continue.
std::optional<int> parse(CLI::App& app, int argc, char** argv);

// A command with subcommands (lfd device list|read, lfd bridge register|...): argv[1] names one
// of `table`, which runs with argv shifted by one. --help/-h prints `usage` (0); no subcommand
// prints it to stderr (2); an unknown one is one line naming `command` and the choices (2).
struct Subcommand {
  const char* name;
  int (*run)(int argc, char** argv);
};
int run_subcommand(const std::string& command, const std::string& usage, std::span<const Subcommand> table,
                   int argc, char** argv);

// Parses "X,Y,Z" (or "WxH" with sep 'x') into numbers; throws InputError naming `option`.
std::vector<double> parse_numbers(const std::string& text, char sep, size_t count,
                                  const std::string& option);

// A view size: "WxH", or with `square` also "N" (N x N); InputError naming `option` for anything
// else or a side outside 1..`max_side`.
display::ViewSize parse_view_size(const std::string& text, const std::string& option, bool square,
                                  int max_side = 16384);

// Where a command's display comes from: a file (--calibration or --display) or a Looking Glass
// attached to this machine (--device auto|SERIAL, searched under --root DIR); one or the other.
struct DisplaySource {
  std::string file, device, root = "/";
  CLI::Option* file_option = nullptr;
  CLI::Option* device_option = nullptr;

  // Adds `file_flag` (e.g. "--calibration"), --device and --root; the first two exclude each
  // other. `required`: the file is required unless --device is given (so that a missing one is
  // reported like any required option).
  void add(CLI::App& app, const std::string& file_flag, const std::string& file_help,
           bool required = true);
  bool given() const { return !file.empty() || !device.empty(); }
  // Reads the file or the device; InputError when neither was given (naming `file_flag`).
  display::Calibration load();
  // The file, or "device LKG-2K-04409" once loaded: for messages.
  const std::string& name() const { return name_; }

 private:
  std::string file_flag_, name_;
};

}  // namespace lfd::apps
