#pragma once
// `lfd camera <name>`: the camera's own calibration, dispatched from the table in camera.cpp.
#include <string>

#include <CLI/CLI.hpp>

#include "calib/camera/camera_calibration.hpp"

namespace lfd::apps {

int RunCameraBoard(int argc, char** argv);      // apps/camera_board.cpp
int RunCameraCalibrate(int argc, char** argv);  // apps/camera_calibrate.cpp

// The board flags both commands share (--squares, --square-mm, --marker-ratio), so the board
// printed and the board looked for are described the same way.
struct CameraBoardFlags {
  std::string squares = "9x6";
  calib::CameraBoardSpec spec;
  void add(CLI::App& app);
  // The spec the flags describe; InputError naming the flag.
  calib::CameraBoardSpec parse() const;
};

}  // namespace lfd::apps
