#pragma once
// Photographs of a panel from eyes between two quilt views (docs/performance.md "Direct panel
// rendering", docs/rendering.md "Photographs between two quilt views"). The quilt path shows a
// viewer between views j and j + 1 one of them (nearest) or a mix (linear); the direct pass shows
// the view at the viewer's own angle. An eye is placed where the display sends the view fraction f
// = (j + 1/2 + t) / V toward it (display/lens_relations.hpp tan_of_seen_fraction, the one
// relation), photographed through the optics simulator (sim/simulator.hpp: the lens model, its
// point spread, the camera), and the photograph is compared with the photograph of what an ideal
// display would show that eye: the per-view render at the continuous view position s = f - 1/2
// (render::QuiltGeometry::view_camera_at) on every subpixel.
//
// The eye stands far (kEyeDistanceInPanelWidths panel widths): a lens sends a view fraction in
// one direction from every point of the panel and the quilt's views are rendered for exactly
// that (off-axis cameras converging on the focal plane), so only a distant eye sees one view
// fraction across the whole panel (within 0.1 views here); a near one sees a different view at
// each point and no single per-view render is "what it should see".
#include <vector>

#include <Eigen/Core>

#include "display/lens_model.hpp"
#include "sim/simulator.hpp"
#include "util/image.hpp"

namespace lfd::validate {

inline constexpr double kEyeDistanceInPanelWidths = 1000.0;

struct EyeBetweenViews {
  int view = 0;              // j of V: between the centres of views j and j + 1
  double between = 0;        // t: 0 on view j's centre, 1 on view j + 1's
  double fraction = 0;       // f = (j + 1/2 + t) / V, seen at the panel centre
  double position_s = 0;     // the continuous view position s = f - 1/2 (QuiltGeometry)
  Eigen::Vector3d eye{0, 0, 1};  // display frame, metres (level with the panel centre)
};

// The eye that sees fraction (j + 1/2 + t) / V at the panel centre, through the cover layer if
// the calibration has one. InputError for j outside 0..V-1 or t outside [0, 1] (or beyond the
// cone at j = V - 1).
EyeBetweenViews eye_between_views(const display::LensModel& lens, int views, int view, double between);

// The panel of an ideal display for one eye: every subpixel shows `view` (the interlacer's tile
// lookup and fringe gain, one view in the quilt), whatever its view fraction.
ImageF single_view_panel(const display::LensModel& lens, const ImageF& view);

// A pinhole photograph from the eye, looking at the panel centre, its horizontal field the
// panel's width as seen from there; `width_px` wide, the panel's aspect. Capture effects:
// the lens point spread `psf_sigma_phase`, `supersample`, 8-bit quantisation, nothing else.
ImageF photograph(const sim::DisplaySimulator& simulator, const ImageF& panel, const EyeBetweenViews& eye,
                  int width_px, double psf_sigma_phase, int supersample);

// PSNR (dB, peak 1) of photograph `a` against `b` over their central 90 % in each direction:
// the panel's edges, foreshortened from an eye off the axis, leave bezel at the sides.
double photo_psnr(const ImageF& a, const ImageF& b);

}  // namespace lfd::validate
