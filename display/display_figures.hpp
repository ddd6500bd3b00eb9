#pragma once
// The figures a person wants to know about a display's calibration, derived once: `lfd info`
// prints them, Python's lfd.Display returns them (docs/python.md).
#include <array>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "display/calibration_file.hpp"
#include "display/lens_model.hpp"
#include "display/view_count.hpp"

namespace lfd::display {

// What `lfd info` shows, derived once from the calibration for every output.
struct DisplayFigures {
  const Calibration& cal;
  const std::string& path;
  const DisplayCalibration& d = cal.display;
  const LensModel lens{d, cal.correction};
  const ViewCountAdvice views = recommend_view_count(cal);
  const double width_mm = d.width_m() * 1000, height_mm = d.height_m() * 1000;
  const double diagonal_in = std::hypot(d.width_m(), d.height_m()) / 0.0254;
  const double lens_period_mm = 25.4 / d.pitch_lpi;
  const std::array<double, 2> range = cal.correction.range();
};

// The figures as JSON (`lfd info --json`, lfd.Display.figures), also the source of the printed
// subpixel layout.
nlohmann::ordered_json figures_json(const DisplayFigures& f);

}  // namespace lfd::display
