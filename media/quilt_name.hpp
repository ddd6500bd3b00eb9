#pragma once
// The `_qs{C}x{R}a{aspect}` quilt name convention (docs/play.md "Conventions";
// docs/file-formats.md "Quilts": the first number is the columns, Alice/LG's
// regex `_qs(\d+)x(\d+)a(\d+.?\d*)`), read without a regex and bounded, so a hostile name
// cannot overflow; and the check that a name does not lie about the file it names.
#include <optional>
#include <string>
#include <string_view>

#include "interlace/quilt_file.hpp"
#include "render/quilt_layout.hpp"

namespace lfd::media {

// Limits of a believable tiling: Looking Glass quilts have at most 11 x 11 tiles (7x7, 11x6,
// 5x9, 8x6); 256 views is display::quilt_grid_for_views's bound.
inline constexpr int kMaxQuiltTilesPerAxis = 256;
inline constexpr int kMaxQuiltViews = 256;
inline constexpr double kMinQuiltAspect = 0.01, kMaxQuiltAspect = 100.0;
// A named tiling "lies" when its tiles come out smaller than this (pixels per side) ...
inline constexpr int kMinQuiltTilePx = 16;
// ... or their pixel shape differs from the named content aspect by more than this factor (the
// real quilts stay within 1.13: the 16" Gen2's 4096^2 5x9 at aspect 1.6 has 1.8-wide tiles).
inline constexpr double kMaxTileAspectMismatch = 2.0;

struct QuiltName {
  int cols = 0, rows = 0;
  double aspect = 0;
};

// The first `_qs{C}x{R}a{aspect}` in `filename` (digits; the aspect with an optional fraction),
// or nullopt when there is none or its numbers are out of the bounds above.
std::optional<QuiltName> parse_quilt_name(std::string_view filename);

// The tiling of a quilt image or video frame of width x height called `name`: from its name,
// then `overrides`; without either, InputError naming it; the aspect defaults to the display's.
// A tiling that does not fit the picture (tiles under kMinQuiltTilePx, a tile shape
// kMaxTileAspectMismatch away from the aspect, more views than tiles) is an InputError
// "NAME: the quilt name says CxR tiles at aspect A but ..." naming the file.
render::QuiltLayout quilt_layout_for(const std::string& name, int width, int height,
                                     const interlace::QuiltOverrides& overrides, double display_aspect);

}  // namespace lfd::media
