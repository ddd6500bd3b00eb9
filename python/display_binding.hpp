#pragma once
// lfd.Display: a display's calibration (visual.json, calibration.json or an attached Looking
// Glass) and the figures derived from it (display/display_figures.hpp, `lfd info`'s).
#include <string>

#include "display/calibration_file.hpp"

namespace lfd::python {

struct PyDisplay {
  display::Calibration calibration;
  std::string name;  // the file, or "device <serial>": for messages
};

}  // namespace lfd::python
