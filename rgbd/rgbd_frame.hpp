#pragma once
// The split of a side-by-side RGB-D frame into its colour and depth halves, and how a depth
// value is read from the depth half (docs/rgbd.md "Frames"). The CPU reference reads the halves
// in place, the GL pass through the same rectangles as texture coordinates: nothing is copied.
#include "rgbd/rgbd_options.hpp"

namespace lfd::rgbd {

// A rectangle of pixels, top-down (row 0 = top, as images on disk).
struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const PixelRect&) const = default;
};

struct RgbdSplit {
  PixelRect colour;
  PixelRect depth;
  // Width / height of the colour half: the aspect of the views (bridge.js's `aspect`).
  double colour_aspect() const { return double(colour.width) / double(colour.height); }
};

// The halves of a width x height frame with the depth half at `location`: each half is
// floor(W/2) x H (left/right) or W x floor(H/2) (top/bottom); an odd middle column or row
// belongs to neither. Throws InputError naming `what` when a half would be empty.
RgbdSplit split_rgbd_frame(int width, int height, DepthLocation location,
                           const std::string& what = "RGB-D frame");

// The rectangle in GL's bottom-up rows (row 0 = bottom) of a frame `height` rows tall, the way
// a texture holds an uploaded image.
PixelRect bottom_up(const PixelRect& rect, int height);

// The normalised depth d in [0, 1] (1 = near) of a depth-half pixel of colour (r, g, b) in
// [0, 1]: grey as the mean of the channels, or with chroma_depth the hue (red 0 -> d = 1, blue
// 240 degrees -> d = 0; hues past blue go to the nearer end of the arc, greys with no
// saturation are far), then 1 - d with depth_inversion. GLSL twin: rgbd/shaders/rgbd_depth.glsl.
float decode_depth(float r, float g, float b, bool chroma_depth, bool depth_inversion);
// The hue (turns, [0, 1)) that encodes depth d in chroma depth: the inverse of decode_depth
// with full saturation and value (for fixtures and tests).
float chroma_hue_of_depth(float depth);

}  // namespace lfd::rgbd
