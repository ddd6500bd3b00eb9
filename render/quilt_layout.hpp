#pragma once
// Quilt conventions (docs/file-formats.md "Quilts"): V views
// in a C x R grid of tiles, view 0 (leftmost camera) in the bottom-left tile, views row-major
// upward; integer tile size floor(W/C) x floor(H/R) anchored at the bottom-left corner (the rest is
// the "viewPortion" margin); file names carry `_qs{C}x{R}a{aspect}`.
#include <optional>
#include <string>

#include "util/default_display.hpp"

namespace lfd::render {

struct QuiltLayout {
  int cols = 5;
  int rows = 9;
  int views = kDefaultViewCount;  // <= cols * rows
  double aspect = 1.0;   // width / height of the content of one tile
  int width = 0;         // texture size in pixels
  int height = 0;

  int tile_width() const { return cols > 0 ? width / cols : 0; }
  int tile_height() const { return rows > 0 ? height / rows : 0; }
  // Top-left pixel of view k's tile in a top-down image (row 0 = top).
  int tile_x(int view) const { return (view % cols) * tile_width(); }
  int tile_y_top_down(int view) const { return height - (view / cols + 1) * tile_height(); }
  // Throws lfd::InputError naming `what` if the layout is unusable.
  void check(const std::string& what) const;
};

// The tiling in a file name such as `scene_qs5x9a1.6.png` (first number = columns).
// Returns nullopt when the name carries none. Sets cols, rows, views = cols*rows, aspect.
std::optional<QuiltLayout> parse_quilt_name(const std::string& filename);

// `_qs{C}x{R}a{aspect}` with the aspect written with up to 4 decimals, trailing zeros dropped.
std::string quilt_suffix(int cols, int rows, double aspect);

// The aspect a quilt of a display is named and interlaced with (docs/file-formats.md "Quilts"):
// `display_aspect` when tiles `tile_height` rows tall at `aspect` are within a pixel of it in
// width (a 16:9 panel's views of 910x512 pixels are 1.7778, not 910/512 = 1.7773, which the
// interlacer would pillarbox by a column), else `aspect` itself; `tile_height` <= 0 snaps nothing.
double snap_to_display_aspect(double aspect, int tile_height, double display_aspect);

}  // namespace lfd::render
