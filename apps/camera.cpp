// lfd camera: the camera's intrinsics from photos of a printed board (and the board to print).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string_view>
#include <vector>

#include "apps/camera.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "util/error.hpp"

namespace lfd::apps {

namespace {

struct CameraCommand {
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

const std::vector<CameraCommand>& camera_commands() {
  static const std::vector<CameraCommand> table = {
      {"board", RunCameraBoard, "write the ChArUco board to print (or show full screen)"},
      {"calibrate", RunCameraCalibrate, "camera intrinsics (camera.yaml) from photos of the board"},
  };
  return table;
}

void print_usage() {
  std::cout << "Usage: lfd camera <command> [options]\n\n"
               "The camera's own calibration, for `lfd calibrate --camera camera.yaml`.\n\n"
               "Commands:\n";
  for (const auto& c : camera_commands()) std::printf("  %-10s %s\n", c.name, c.summary);
  std::cout << "\nRun 'lfd camera <command> --help' for its options; docs/calibration.md has the\n"
               "photographing guide.\n";
}

}  // namespace

void CameraBoardFlags::add(CLI::App& app) {
  app.add_option("--squares", squares, "board squares, across x down (e.g. 9x6)")
      ->capture_default_str();
  app.add_option("--square-mm", spec.square_mm,
                 "side of one printed square in mm (measure it after printing)")
      ->capture_default_str();
  app.add_option("--marker-ratio", spec.marker_ratio, "marker side / square side")
      ->capture_default_str();
}

calib::CameraBoardSpec CameraBoardFlags::parse() const {
  calib::CameraBoardSpec out = spec;
  const auto n = parse_numbers(squares, 'x', 2, "--squares");
  if (n[0] != std::floor(n[0]) || n[1] != std::floor(n[1]))
    throw_input_error("--squares: {}: whole numbers of squares, e.g. 9x6", squares);
  out.squares_x = int(n[0]);
  out.squares_y = int(n[1]);
  out.check();
  return out;
}

int RunCamera(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    print_usage();
    return argc < 2 ? 2 : 0;
  }
  const std::string_view name = argv[1];
  for (const auto& c : camera_commands())
    if (name == c.name) return c.run(argc - 1, argv + 1);
  std::cerr << "lfd camera: unknown command '" << name << "' (see lfd camera --help)\n";
  return 2;
}

}  // namespace lfd::apps
