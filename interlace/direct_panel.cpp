// The direct panel pass (interlace/direct_panel.hpp): one job per panel row; the row's rays
// (three per pixel inside the fitted view) go to render::PlaneRays, which finds each plane's
// row once for them all.
#include "interlace/direct_panel.hpp"

#include <cmath>
#include <vector>

#include "interlace/interlacer.hpp"
#include "render/plane_rays.hpp"

namespace lfd::interlace {

double panel_view_fraction(const display::LensModel& lens, bool invert_views, int x, int row, int channel) {
  const double f = lens.subpixel_view_fraction(x, row, channel);
  return invert_views ? 1.0 - f : f;
}

ImageF render_direct_panel(const render::SweepingPlanes& planes, const render::QuiltGeometry& geometry,
                           const render::ReferenceCamera& ref, const display::LensModel& lens,
                           const DirectPanelOptions& options) {
  const auto& cal = lens.calibration();
  ImageF panel(cal.screen_w, cal.screen_h, 3, 0.0f);
  const render::PlaneRays rays(planes, geometry, ref, options.filter, options.background, options.kernel);
  const AspectFit fit =
      aspect_fit(cal, double(geometry.base.width) / double(geometry.base.height), options.overscan,
                 geometry.base.height);
  // Fractions lie in [0, 1]: offsets within the cone's edges s = +-1/2.
  const float max_abs_dx = std::abs(geometry.view_offset_at(0.5f));
  // view_offset_at is linear in the position: its slope once, not a tan() per subpixel.
  const float offset_per_position = geometry.view_offset_at(1.0f);
#pragma omp parallel
  {
    std::vector<render::PlaneRay> row_rays;
    std::vector<float> values;
    std::vector<double> fractions(3 * size_t(cal.screen_w));
    render::PlaneRays::Scratch scratch;
#pragma omp for schedule(dynamic, 8)
    for (int row = 0; row < cal.screen_h; ++row) {
      row_rays.clear();
      // The fitted view covers one run of the row's pixels (the fit is affine in x): its rays
      // in order, three per pixel, so ray i is subpixel 3 x_first + i of the row.
      int x_first = -1;
      double tile_v = 0;
      lens.row_view_fractions(row, fractions.data());
      for (int x = 0; x < cal.screen_w; ++x) {
        const TilePoint t = tile_point(lens, fit, x, row);
        if (!t.inside) continue;
        if (x_first < 0) x_first = x;
        tile_v = t.v;  // the same for every pixel of the row
        const float u_ndc = float(2.0 * t.u - 1.0);
        for (int c = 0; c < 3; ++c) {
          // panel_view_fraction, from the row's fractions.
          const double lens_f = fractions[3 * size_t(x) + size_t(c)];
          const double f = options.invert_views ? 1.0 - lens_f : lens_f;
          row_rays.push_back({offset_per_position * view_position_of_fraction(f), u_ndc, c});
        }
      }
      if (row_rays.empty()) continue;
      // Base-camera NDC of the view row, top-down as the planes' rows ((2 y + 1) / H - 1 at tile
      // row y, v = 1 - (y + 1/2) / H).
      rays.composite_row(float(1.0 - 2.0 * tile_v), max_abs_dx, row_rays, values, scratch);
      const double gain = fringe_gain(cal, row);
      float* out = &panel.at(x_first, row, 0);
      for (size_t i = 0; i < row_rays.size(); ++i) out[i] = float(values[i] * gain);
    }
  }
  return panel;
}

}  // namespace lfd::interlace
