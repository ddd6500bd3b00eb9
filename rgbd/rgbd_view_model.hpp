#pragma once
// Where a pixel of an RGB-D image moves in each view of a quilt (docs/rgbd.md "The view model").
// The views are the quilt's view cameras (render::QuiltGeometry, the same s_j and principal-
// point shifts p_j as every lfd renderer) around a pinhole camera of the default field of view
// that took the colour half; the depth map is read as a relief about the focal plane, so a pixel
// of normalised depth d (1 = near) lies at z-ratio q(d) = 1 - D_focal / Z and moves, in view j,
// by p_j q(d) tile half-widths:
//
//   q(d)        = depthiness * kReliefRatio * (0.5 - d) + focus
//   shift_j(d)  = p_j * q(d) * W_tile / 2       (pixels, + right; only horizontal)
//
// The zero-parallax depth is d_0 = 0.5 + focus / (depthiness * kReliefRatio).
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "rgbd/rgbd_options.hpp"
#include "util/default_display.hpp"

namespace lfd::rgbd {

// The relief's depth (front to back, at depthiness 1) as a fraction of the focal distance: at
// bridge.js's default depthiness 1.5, 40-degree cone and the default 40-degree camera, the
// outermost views move the nearest and farthest pixels by about +-3.7 % of the tile width.
inline constexpr double kReliefRatio = 0.1;

// The quilt geometry of RGB-D views: a camera at the origin looking along +z with the default
// vertical field of view (render::kDefaultFovYDeg) and the tile's aspect, focal distance 1, the
// display's view cone and layout.views views. Throws InputError for an unusable layout or cone.
render::QuiltGeometry rgbd_quilt_geometry(const render::QuiltLayout& layout,
                                          double view_cone_deg = kDefaultViewConeDeg);

// q(d) above.
float relief_z_ratio(float depth, const RgbdOptions& options);
// d_0 above: the depth that does not move.
double zero_parallax_depth(const RgbdOptions& options);

// The shift of view j per unit of z-ratio, p_j * W_tile / 2 in pixels, so shift_j(d) =
// view_shift_px_per_z_ratio(j) * q(d). GLSL twin: rgbd/shaders/rgbd_warp.frag.glsl.
float view_shift_px_per_z_ratio(const render::QuiltGeometry& geometry, int view, int tile_width);
// shift_j(d) in pixels.
float view_shift_px(const render::QuiltGeometry& geometry, int view, int tile_width, float depth,
                    const RgbdOptions& options);

// The layout of the quilt an RGB-D frame becomes: the colour half's aspect, display::
// quilt_grid_for_views for `views`, tiles `tile_height` pixels tall (0: the colour half's height)
// and as wide as the aspect says. Throws InputError for a bad frame or view count.
render::QuiltLayout rgbd_quilt_layout(int frame_width, int frame_height, DepthLocation location,
                                      int views = kDefaultViewCount, int tile_height = 0);

}  // namespace lfd::rgbd
