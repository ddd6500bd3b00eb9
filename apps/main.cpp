// The `lfd` program: a table of subcommands, each in its own file (apps/<name>.cpp).
#include <cstring>
#include <exception>
#include <functional>
#include <iostream>
#include <string_view>
#include <vector>

#include "apps/commands.hpp"
#include "util/data_dir.hpp"
#include "util/error.hpp"
#include "util/version.hpp"

namespace {

// `lfd version`: the version line and where the program finds its bundled data.
int RunVersion(int argc, char** argv) {
  if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::cout << "Print the version, the git commit and the build date, and the folder of the\n"
                 "bundled data (display templates, the demo scene; $LFD_DATA_DIR overrides it).\n"
                 "\nUsage: lfd version   (or lfd --version: the first line only)\n";
    return 0;
  }
  if (argc > 1) lfd::throw_input_error("version takes no arguments (got '{}')", argv[1]);
  std::cout << lfd::version_line() << "\ndata: " << lfd::data_dir().string() << "\n";
  return 0;
}

struct Command {
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

const std::vector<Command>& commands() {
  using namespace lfd::apps;
  static const std::vector<Command> table = {
#ifndef LFD_RENDER_ONLY
      {"demo", RunDemo, "run the whole pipeline on the bundled data and write a report"},
#endif
      {"info", RunInfo, "print the figures derived from a calibration"},
      {"interlace", RunInterlace, "interlace a quilt into a panel image for a display"},
      {"scene", RunScene, "generate a procedural Gaussian scene or inspect a scene file"},
      {"render", RunRender, "render a Gaussian scene into a light-field quilt (G2LF or per view)"},
      {"view", RunView, "show a Gaussian scene on the display in real time (GL, with controls)"},
#ifndef LFD_NO_PLAYBACK  // a renderer-only build without FFmpeg (-DLFD_WITH_PLAYBACK=OFF)
      {"play", RunPlay, "play quilt images and quilt videos on the display (playlists, keys)"},
      {"record", RunRecord, "record a quilt video of a scene along a camera path (turntable, keyframes)"},
#endif
      {"compare", RunCompare, "PSNR and SSIM between two images"},
      {"device", RunDevice, "list attached Looking Glass units and read their calibration"},
      {"bridge", RunBridge, "let the Bridge SDK's clients load lfd's libbridge_inproc (register, status)"},
      {"bench", RunBench, "speed benchmarks: tables and JSON (lfd bench --help)"},
      {"rgbd-quilt", RunRgbdQuilt, "turn an RGB-D image (colour + depth side by side) into a quilt"},
#ifndef LFD_NO_PLAYBACK
      {"serve", RunServe, "serve the display to existing Looking Glass apps (HoloPlay, Bridge)"},
#endif
#ifndef LFD_RENDER_ONLY  // the renderer-only build has no OpenCV or Ceres
      {"simulate", RunSimulate, "simulate a camera photograph of a display showing a panel"},
      {"validate", RunValidate, "measure crosstalk and view separation of a display"},
      {"patterns", RunPatterns, "write the calibration patterns for a display"},
      {"calibrate", RunCalibrate, "calibrate a display unit from photographs of the patterns"},
      {"camera", RunCamera, "calibrate the camera from photos of a printed board (lfd camera --help)"},
#endif
      {"version", RunVersion, "print the version, the git commit and the data folder"},
  };
  return table;
}

void print_usage() {
  std::cout << "lfd: light field display toolkit\n\nUsage: lfd <command> [options]\n\n"
               "Commands:\n";
  for (const auto& c : commands()) std::printf("  %-11s %s\n", c.name, c.summary);
  std::cout << "\nRun 'lfd <command> --help' for a command's options and examples,\n"
               "'lfd --version' for the version and the git commit it was built from.\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    print_usage();
    return argc < 2 ? 2 : 0;
  }
  if (std::strcmp(argv[1], "--version") == 0 || std::strcmp(argv[1], "-V") == 0) {
    std::cout << lfd::version_line() << "\n";
    return 0;
  }
  const std::string_view name = argv[1];
  for (const auto& c : commands()) {
    if (name != c.name) continue;
    try {
      return c.run(argc - 1, argv + 1);
    } catch (const lfd::InputError& e) {
      std::cerr << "lfd " << name << ": error: " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "lfd " << name << ": failed: " << e.what() << "\n";
      return 1;
    }
  }
  std::cerr << "lfd: unknown command '" << name << "' (see lfd --help)\n";
  return 2;
}
