#include "interlace/interlacer.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "util/error.hpp"

namespace lfd::interlace {

ViewBlend parse_view_blend(const std::string& name) {
  if (name == "nearest") return ViewBlend::kNearest;
  if (name == "linear") return ViewBlend::kLinear;
  throw_input_error("interlace options: blend: '{}' is not nearest or linear", name);
}

const char* view_blend_name(ViewBlend blend) {
  return blend == ViewBlend::kLinear ? "linear" : "nearest";
}

Interlacer::Interlacer(const display::LensModel& lens, const render::QuiltLayout& layout,
                       InterlaceOptions options)
    : lens_(lens), layout_(layout), options_(options) {
  layout_.check("quilt");
  fit_ = aspect_fit(lens.calibration(), layout_.aspect, options_.overscan, layout_.tile_height());
}

AspectFit aspect_fit(const display::DisplayCalibration& cal, double view_aspect, bool overscan, int tile_height_px) {
  const double display_aspect = double(cal.screen_w) / cal.screen_h;
  view_aspect = render::snap_to_display_aspect(view_aspect, tile_height_px, display_aspect);
  const bool fit_x = (display_aspect >= view_aspect && !overscan) || (display_aspect <= view_aspect && overscan);
  return fit_x ? AspectFit{display_aspect / view_aspect, 1.0} : AspectFit{1.0, view_aspect / display_aspect};
}

TilePoint tile_point(const display::LensModel& lens, double view_aspect, bool overscan, int x, int row) {
  return tile_point(lens, aspect_fit(lens.calibration(), view_aspect, overscan), x, row);
}

double fringe_gain(const display::DisplayCalibration& cal, int row) {
  const int j = cal.screen_h - 1 - row;
  return 1.0 - std::abs(cal.fringe) * std::floor(std::fmod(j + 0.5 + std::ceil(cal.fringe / 2), 2.0));
}

SubpixelSample Interlacer::sample_for(int x, int row, int channel) const {
  const TilePoint point = tile_point(lens_, fit_, x, row);
  return sample_at(point, point.inside ? lens_.subpixel_view_fraction(x, row, channel) : 0.0);
}

SubpixelSample Interlacer::sample_at(const TilePoint& point, double lens_fraction) const {
  SubpixelSample s;
  s.tile_u = point.u;
  s.tile_v = point.v;
  if (!point.inside) {
    s.inside = false;
    return s;
  }

  const int views = layout_.views;
  double f = lens_fraction;
  if (options_.invert_views) f = 1.0 - f;
  if (options_.blend == ViewBlend::kNearest) {
    s.view_a = s.view_b = display::LensModel::view_index(f, views);
    return s;
  }
  // Linear: blend the two views whose centres (k + 0.5)/V bracket f; clamp at the cone edges
  // rather than wrapping, since the first and last views are the farthest apart in content.
  const double t = std::clamp(f * views - 0.5, 0.0, double(views - 1));
  s.view_a = std::min(int(std::floor(t)), views - 1);
  s.view_b = std::min(s.view_a + 1, views - 1);
  s.weight_b = float(t - s.view_a);
  return s;
}

float Interlacer::sample_tile(const ImageF& quilt, int view, double u, double v,
                              int channel) const {
  const int th = layout_.tile_height();
  const auto [x0, x1, y0, y1, ax, ay] = tile_texels(u, v);
  const int ox = layout_.tile_x(view);
  const int oy = layout_.tile_y_top_down(view) + th - 1;  // image row of tile texel row 0
  auto at = [&](int ix, int iy) { return quilt.at(ox + ix, oy - iy, channel); };
  const float top = at(x0, y0) * (1 - ax) + at(x1, y0) * ax;
  const float bottom = at(x0, y1) * (1 - ax) + at(x1, y1) * ax;
  return top * (1 - ay) + bottom * ay;
}

Interlacer::TileTexels Interlacer::tile_texels(double u, double v) const {
  const int tw = layout_.tile_width(), th = layout_.tile_height();
  // Texel centres at (i + 0.5)/tw; bottom-up texel coordinates within the tile.
  const double tx = std::clamp(u * tw - 0.5, 0.0, double(tw - 1));
  const double ty = std::clamp(v * th - 0.5, 0.0, double(th - 1));
  TileTexels t;
  t.x0 = int(tx);
  t.y0 = int(ty);
  t.x1 = std::min(t.x0 + 1, tw - 1);
  t.y1 = std::min(t.y0 + 1, th - 1);
  t.ax = float(tx - t.x0);
  t.ay = float(ty - t.y0);
  return t;
}

ImageF Interlacer::interlace(const ImageF& quilt) const {
  if (quilt.width != layout_.width || quilt.height != layout_.height)
    throw_input_error("quilt: image is {}x{} but the layout says {}x{}", quilt.width,
                      quilt.height, layout_.width, layout_.height);
  const auto& cal = lens_.calibration();
  ImageF panel(cal.screen_w, cal.screen_h, 3, 0.0f);
  const int channels = quilt.channels;
#pragma omp parallel
  {
    std::vector<double> fractions(3 * size_t(cal.screen_w));
#pragma omp for schedule(dynamic, 8)
  for (int row = 0; row < cal.screen_h; ++row) {
    const double row_gain = fringe_gain(cal, row);
    lens_.row_view_fractions(row, fractions.data());
    for (int x = 0; x < cal.screen_w; ++x) {
      const TilePoint point = tile_point(lens_, fit_, x, row);
      if (!point.inside) continue;
      for (int c = 0; c < 3; ++c) {
        const SubpixelSample s = sample_at(point, fractions[3 * size_t(x) + size_t(c)]);
        const int qc = channels >= 3 ? c : 0;
        float value = sample_tile(quilt, s.view_a, s.tile_u, s.tile_v, qc);
        if (s.weight_b > 0) {
          const float b = sample_tile(quilt, s.view_b, s.tile_u, s.tile_v, qc);
          value += (b - value) * s.weight_b;
        }
        panel.at(x, row, c) = float(value * row_gain);
      }
    }
  }
  }
  return panel;
}

ImageF interlace(const ImageF& quilt, const render::QuiltLayout& layout,
                 const display::LensModel& lens, const InterlaceOptions& options) {
  return Interlacer(lens, layout, options).interlace(quilt);
}

}  // namespace lfd::interlace
