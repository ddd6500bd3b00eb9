#pragma once
// The CPU reference interlacer (docs/display-model.md "Phase and view" and
// "Vendor interlacing rules"): for each panel subpixel, its view fraction from the lens
// model (correction field and Gen3 cells included), a view index (nearest, or a linear blend of
// the two nearest view centres), and a bilinear lookup inside that view's quilt tile
// (aspect/overscan and viewPortion handled as Looking Glass software does). The GLSL
// interlacer must match this function.
#include <string>

#include "display/lens_model.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::interlace {

enum class ViewBlend { kNearest, kLinear };

// "nearest" | "linear" (the --blend of every command); InputError "interlace options: blend:
// ..." otherwise.
ViewBlend parse_view_blend(const std::string& name);
const char* view_blend_name(ViewBlend blend);

struct InterlaceOptions {
  ViewBlend blend = ViewBlend::kNearest;
  bool overscan = false;      // fill the panel and crop instead of fitting with black bars
  bool invert_views = false;  // user "quilt invert": read views in reverse order
};

// Where in the quilt one panel subpixel reads from: tile `view_a` (and `view_b` with weight
// `weight_b` when blending), at tile coordinates (tile_u, tile_v) in [0, 1] (v up).
struct SubpixelSample {
  bool inside = true;  // false: outside the fitted quilt area (black)
  int view_a = 0;
  int view_b = 0;
  float weight_b = 0.f;
  double tile_u = 0, tile_v = 0;
};

// The aspect fit (docs/display-model.md "Vendor interlacing rules") of a view of aspect
// `view_aspect` (width / height) on the panel: where pixel (x, row) falls in it, (u, v) in [0, 1]
// with v up, or inside = false in the black bars (the crop under overscan). The lens phase uses the
// unscaled pixel position; only this lookup is scaled. Interlacer::sample_for and the direct panel
// pass (interlace/direct_panel.hpp) both call it.
// The aspect fit as the scale of (u - 1/2, v - 1/2): one of them is 1.
struct AspectFit {
  double scale_u = 1, scale_v = 1;
};
// Views `tile_height_px` rows tall whose aspect is within a pixel of the panel's are fitted as the
// panel's (render::snap_to_display_aspect: no black column for a 910x512 view of a 16:9 panel);
// 0 takes `view_aspect` as it is.
AspectFit aspect_fit(const display::DisplayCalibration& calibration, double view_aspect, bool overscan,
                     int tile_height_px = 0);

struct TilePoint {
  bool inside = true;
  double u = 0, v = 0;
};
TilePoint tile_point(const display::LensModel& lens, double view_aspect, bool overscan, int x, int row_top_down);
// The same with the aspect fit computed once (per panel, not per pixel); inline, as it is called
// per pixel.
inline TilePoint tile_point(const display::LensModel& lens, const AspectFit& fit, int x, int row_top_down) {
  const display::ScreenUV p = lens.pixel_uv(x, row_top_down);
  TilePoint t{true, (p.u - 0.5) * fit.scale_u + 0.5, (p.v - 0.5) * fit.scale_v + 0.5};
  t.inside = !(t.u < 0 || t.u > 1 || t.v < 0 || t.v > 1);
  return t;
}

// The fringe correction (docs/display-model.md "Vendor interlacing rules"): the gain of panel
// row `row_top_down`, every other row darkened by |fringe|.
double fringe_gain(const display::DisplayCalibration& calibration, int row_top_down);

class Interlacer {
 public:
  Interlacer(const display::LensModel& lens, const render::QuiltLayout& layout,
             InterlaceOptions options = {});

  // Throws InputError if the quilt image does not match the layout's size.
  ImageF interlace(const ImageF& quilt) const;

  SubpixelSample sample_for(int x, int row_top_down, int channel) const;
  // The same from the subpixel's tile point and its lens view fraction (before invert_views):
  // interlace() takes both a row at a time (LensModel::row_view_fractions).
  SubpixelSample sample_at(const TilePoint& point, double lens_fraction) const;
  // Bilinear lookup of channel c of view `view` at tile coordinates (u, v), clamped inside
  // the tile so no neighbouring view bleeds in.
  float sample_tile(const ImageF& quilt, int view, double u, double v, int channel) const;
  // The four texels (and weights) that lookup reads: columns x0, x1 and bottom-up rows y0, y1
  // of the tile (the view image's rows th - 1 - y, top-down). sample_tile reads exactly these;
  // the per-view masks (view_masks.hpp) mark them.
  struct TileTexels {
    int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    float ax = 0, ay = 0;
  };
  TileTexels tile_texels(double u, double v) const;
  const render::QuiltLayout& layout() const { return layout_; }
  const display::LensModel& lens() const { return lens_; }

 private:
  const display::LensModel& lens_;
  render::QuiltLayout layout_;
  InterlaceOptions options_;
  AspectFit fit_;
};

// Convenience: interlace a quilt image for a display.
ImageF interlace(const ImageF& quilt, const render::QuiltLayout& layout,
                 const display::LensModel& lens, const InterlaceOptions& options = {});

}  // namespace lfd::interlace
