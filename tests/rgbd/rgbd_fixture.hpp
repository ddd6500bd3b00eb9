#pragma once
// The synthetic RGB-D fixture of the rgbd tests (docs/rgbd.md "Tests"), generated in code: a
// colour half of flat layers at known depths beside its depth half, so every view's shift of
// every layer is known. Colour encodes where a pixel came from: r the source column (unique per
// column), g the layer, b the row; no pixel is black, so a black pixel is an unfilled hole.
#include <algorithm>
#include <cmath>

#include "rgbd/rgbd_frame.hpp"
#include "util/image.hpp"

namespace lfd::rgbd::test {

struct Layer {
  int row0, row1;  // rows [row0, row1) of the colour half, all columns in [col0, col1)
  int col0, col1;
  float depth;     // normalised, 1 = near
  int id;
};

// Background (id 0, far) everywhere; a focus-plane band (id 1, d = 0.5) in the second quarter
// of the rows and a near band (id 2, d = 1) in the third, each inset from the sides by a
// quarter of the width.
inline Layer background_layer(int w, int h) { return {0, h, 0, w, 0.0f, 0}; }
inline Layer focus_layer(int w, int h) { return {h / 4, h / 2, w / 4, w - w / 4, 0.5f, 1}; }
inline Layer near_layer(int w, int h) { return {h / 2, 3 * h / 4, w / 4, w - w / 4, 1.0f, 2}; }

inline float column_code(int x, int w) { return 0.1f + 0.8f * float(x) / float(w - 1); }
inline float layer_code(int id) { return 0.2f + 0.3f * float(id); }
inline float row_code(int y, int h) { return 0.5f + 0.4f * float(y) / float(h - 1); }

// The layer a colour-half pixel belongs to (the last listed that covers it).
inline Layer layer_at(int x, int y, int w, int h) {
  Layer found = background_layer(w, h);
  for (const Layer& l : {focus_layer(w, h), near_layer(w, h)})
    if (y >= l.row0 && y < l.row1 && x >= l.col0 && x < l.col1) found = l;
  return found;
}

// HSV (hue in turns, full saturation and value) to RGB.
inline void hue_to_rgb(float hue, float rgb[3]) {
  for (int c = 0; c < 3; ++c) {
    const float k = std::fmod(float(5 - 2 * c) + hue * 6.0f, 6.0f);  // r: n=5, g: 3, b: 1
    rgb[c] = 1.0f - std::max(0.0f, std::min({k, 4.0f - k, 1.0f}));
  }
}

// The side-by-side frame: colour w x h, depth beside it at `location`; depth as grey or hue
// (chroma), written inverted (black near) when `inverted`.
inline ImageF layered_rgbd_frame(int w, int h, DepthLocation location, bool chroma = false,
                                 bool inverted = false) {
  const bool side = location == DepthLocation::left || location == DepthLocation::right;
  ImageF frame(side ? 2 * w : w, side ? h : 2 * h, 3);
  const RgbdSplit split = split_rgbd_frame(frame.width, frame.height, location);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Layer l = layer_at(x, y, w, h);
      float* c = &frame.at(split.colour.x + x, split.colour.y + y, 0);
      c[0] = column_code(x, w);
      c[1] = layer_code(l.id);
      c[2] = row_code(y, h);
      const float d = inverted ? 1.0f - l.depth : l.depth;
      float* z = &frame.at(split.depth.x + x, split.depth.y + y, 0);
      if (chroma) hue_to_rgb(chroma_hue_of_depth(d), z);
      else z[0] = z[1] = z[2] = d;
    }
  return frame;
}

}  // namespace lfd::rgbd::test
