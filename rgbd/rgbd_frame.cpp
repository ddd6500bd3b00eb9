#include "rgbd/rgbd_frame.hpp"

#include <algorithm>
#include <cmath>

#include "util/error.hpp"

namespace lfd::rgbd {

// Hue arc of chroma depth: red (0) near to blue (2/3 turn) far (docs/rgbd.md "Chroma depth").
inline constexpr float kChromaFarHue = 2.0f / 3.0f;

RgbdSplit split_rgbd_frame(int width, int height, DepthLocation location, const std::string& what) {
  if (width < 1 || height < 1) throw_input_error("{}: empty ({}x{})", what, width, height);
  RgbdSplit s;
  const int hw = width / 2, hh = height / 2;
  switch (location) {
    case DepthLocation::right:
      s.colour = {0, 0, hw, height};
      s.depth = {width - hw, 0, hw, height};
      break;
    case DepthLocation::left:
      s.depth = {0, 0, hw, height};
      s.colour = {width - hw, 0, hw, height};
      break;
    case DepthLocation::top:
      s.depth = {0, 0, width, hh};
      s.colour = {0, height - hh, width, hh};
      break;
    case DepthLocation::bottom:
      s.colour = {0, 0, width, hh};
      s.depth = {0, height - hh, width, hh};
      break;
    default:
      throw_input_error("{}: depth_loc {} must be 0..3", what, int(location));
  }
  if (s.colour.width < 1 || s.colour.height < 1)
    throw_input_error("{}: {}x{} is too small to split with the depth at the {}", what, width,
                      height, depth_location_name(location));
  return s;
}

PixelRect bottom_up(const PixelRect& rect, int height) {
  return {rect.x, height - rect.y - rect.height, rect.width, rect.height};
}

float decode_depth(float r, float g, float b, bool chroma_depth, bool depth_inversion) {
  float d = 0.0f;
  if (!chroma_depth) {
    d = (r + g + b) / 3.0f;
  } else {
    // HSV hue in turns; its arc from red (near) to blue (far) is the depth.
    const float mx = std::max({r, g, b}), mn = std::min({r, g, b});
    const float c = mx - mn;
    if (c <= 0.0f) {
      d = 0.0f;  // a grey carries no hue: far
    } else {
      float h;
      if (mx == r) h = (g - b) / c;
      else if (mx == g) h = 2.0f + (b - r) / c;
      else h = 4.0f + (r - g) / c;
      h /= 6.0f;
      if (h < 0.0f) h += 1.0f;
      // Past blue (magenta) belongs to the nearer end of the arc: red if closer to red.
      if (h > kChromaFarHue) h = h > 0.5f * (1.0f + kChromaFarHue) ? 0.0f : kChromaFarHue;
      d = 1.0f - h / kChromaFarHue;
    }
  }
  d = std::clamp(d, 0.0f, 1.0f);
  return depth_inversion ? 1.0f - d : d;
}

float chroma_hue_of_depth(float depth) {
  return (1.0f - std::clamp(depth, 0.0f, 1.0f)) * kChromaFarHue;
}

}  // namespace lfd::rgbd
