#pragma once
// The per-display values HoloPlay Core exported and Bridge's getters still answer
// (docs/bridge-inproc.md "Getters"): some are visual.json's raw values, the others the shader
// uniforms derived from them by display::shader_terms (docs/display-model.md), the one
// definition lfd's interlacer uses.
#include "display/display_calibration.hpp"

namespace lfd::bridge {

struct HoloPlayValues {
  int invview = 1;          // raw invView
  int ri = 0, bi = 2;       // red and blue subpixel index: (2, 0) with flipSubp
  float tilt = 0;           // shader: H / (W slope), negated by flipImageX
  float displayaspect = 1;  // W / H
  float fringe = 0;         // raw
  float subp = 0;           // shader: one subpixel as a fraction of the width, 1 / (3 W)
  float pitch = 0;          // shader: lens periods across the width, pitch (W / DPI) cos(atan(1/slope))
  float center = 0;         // raw, lens periods
  float viewcone = 40;      // raw, degrees
};

HoloPlayValues holoplay_values(const display::DisplayCalibration& calibration);

}  // namespace lfd::bridge
