#pragma once
// Direct panel rendering (docs/rendering.md "Direct panel rendering"): the panel straight from the
// sweeping planes, with no quilt. Each panel subpixel shows the view fraction the lens model gives
// it (display::LensModel: correction field and Gen3 cells included, the relation the interlacer
// uses); that fraction stands for a camera at the continuous view position s = f - 1/2 (the quilt's
// view j sits at the centre (j + 1/2) / V - 1/2 of the fractions that select it), and the planes
// are composited along the ray of that camera through the subpixel's point in the view (the
// interlacer's aspect fit) for the subpixel's colour channel alone. At a fraction on a view centre
// this is the quilt path's ray exactly; between them the quilt path rounds (nearest) or mixes two
// views (linear), this does neither.
#include <glm/glm.hpp>

#include "display/lens_model.hpp"
#include "render/plane_samples.hpp"
#include "render/quilt_geometry.hpp"
#include "render/sweeping_planes.hpp"
#include "render/swizzle_blend.hpp"
#include "util/image.hpp"

namespace lfd::interlace {

struct DirectPanelOptions {
  // Bilinear: closer to the continuous views than nearest, whose box reconstruction on the
  // plane's texel grid is off by up to half a texel's change at every subpixel, decorrelated
  // between neighbours by their view offsets (docs/rendering.md "Which plane filter").
  render::PlaneFilter filter = render::PlaneFilter::kBilinear;
  glm::vec3 background{0.0f};
  bool overscan = false;      // InterlaceOptions::overscan
  bool invert_views = false;  // InterlaceOptions::invert_views
  // The sampling loop (render/plane_samples.hpp): the fastest this CPU has unless told.
  render::SampleKernel kernel = render::sample_window_kernel();
};

// The continuous view position a view fraction stands for: s = f - 1/2 (QuiltGeometry's
// view_position(j) is this at f = (j + 1/2) / V).
inline float view_position_of_fraction(double fraction) { return float(fraction - 0.5); }

// The subpixel's view fraction as the interlacer reads it: the lens model's, reversed under
// invert_views.
double panel_view_fraction(const display::LensModel& lens, bool invert_views, int x, int row_top_down,
                           int channel);

// The panel (screenW x screenH RGB, rows top-down, black outside the fitted view, the fringe
// gain applied) from the planes of `ref` for the views of `geometry`.
ImageF render_direct_panel(const render::SweepingPlanes& planes, const render::QuiltGeometry& geometry,
                           const render::ReferenceCamera& ref, const display::LensModel& lens,
                           const DirectPanelOptions& options);

}  // namespace lfd::interlace
