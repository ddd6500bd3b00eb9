#include "display/cover_layer.hpp"

#include <array>
#include <string_view>

namespace lfd::display {

namespace {

struct Family {
  std::string_view serial_prefix, name;
  int screen_w, screen_h;
  double dpi;
  CoverLayer cover;
};

// Thicknesses are estimates, not measurements: Looking Glass publishes none. Gen1 units and the
// Portrait are a visibly thick PMMA block whose depth is a large part of the unit's (the image
// floats inside it; Looking Glass's forum, "pixel layout": the block widens the field of view;
// docs/display-model.md "The cover layer");
// Gen2 keeps a thinner block; Gen3 and Go are flat panels behind a cover glass (n = 1.52,
// soda-lime). A measured value belongs in calibration.json's "cover". What an error in t costs
// is measured in docs/calibration.md (`lfd bench calibration --solver-without-cover`).
// How far off they may be: a quarter of a block's estimate (a block's depth is judged from the
// unit's photos and its depth), 1 mm of a cover glass (1-3 mm are usual).
constexpr double kAcrylic = 1.49, kGlass = 1.52;
constexpr double kBlockTolerance = 0.25, kGlassToleranceM = 0.001;
double tolerance_m(const CoverLayer& c) {
  return c.refractive_index == kGlass ? kGlassToleranceM : kBlockTolerance * c.thickness_m;
}
constexpr std::array kFamilies{
    Family{"LKG-2K", "Gen1 8.9\"", 2560, 1600, 338, {0.025, kAcrylic}},
    Family{"LKG-4K", "Gen1 15.6\"", 3840, 2160, 283, {0.030, kAcrylic}},
    Family{"LKG-PORT", "Portrait", 1536, 2048, 324, {0.020, kAcrylic}},
    Family{"LKG-A", "16\" Gen2", 3840, 2160, 283, {0.015, kAcrylic}},
    Family{"LKG-B", "32\" Gen2", 7680, 4320, 280, {0.020, kAcrylic}},
    Family{"LKG-H", "16\" Gen3 portrait", 2160, 3840, 283, {0.002, kGlass}},
    Family{"LKG-J", "16\" Gen3 landscape", 3840, 2160, 283, {0.002, kGlass}},
    Family{"LKG-E", "Go", 1440, 2560, 491, {0.002, kGlass}},
};

}  // namespace

CoverDefault cover_layer_for_family(const DisplayCalibration& d) {
  for (const Family& f : kFamilies)
    if (d.serial.starts_with(f.serial_prefix))
      return {f.cover, std::string(f.name), tolerance_m(f.cover)};
  // Gen1 units read over HID carry a bare number as serial: the panel names the family when
  // only one family has it (3840x2160 at 283 DPI is three families', which stay unknown).
  const Family* match = nullptr;
  int matches = 0;
  for (const Family& f : kFamilies)
    if (d.screen_w == f.screen_w && d.screen_h == f.screen_h && d.dpi == f.dpi) {
      match = &f;
      ++matches;
    }
  if (matches == 1) return {match->cover, std::string(match->name), tolerance_m(match->cover)};
  return {CoverLayer{0.0, kAcrylic}, "unknown"};
}

}  // namespace lfd::display
