#pragma once
// The CPU reference of RGB-D to quilt (docs/rgbd.md "Rendering"): depth-image-based rendering in
// three named stages, each the twin of one GL pass of rgbd/gl_rgbd_views.hpp:
//   resample_rgbd   the colour and depth halves at tile resolution, through zoom and crop
//                   (colour bilinear, depth nearest, so no depth between surfaces is invented);
//   warp_view       every pixel moved along its row by shift_j(d) to the pixel its centre lands
//                   in, the nearest (largest d) winning where several land (the z-test);
//   fill_holes      each pixel nothing landed on takes the colour of the farther of its nearest
//                   covered neighbours left and right on its row (the background side).
#include <vector>

#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "rgbd/rgbd_options.hpp"
#include "util/default_display.hpp"
#include "util/image.hpp"

namespace lfd::rgbd {

// Colour (RGB) and normalised depth (1 = near) of the content at tile resolution, top-down.
struct RgbdSource {
  int width = 0, height = 0;
  ImageF colour;             // 3 channels
  std::vector<float> depth;  // width * height
  float depth_at(int x, int y) const { return depth[size_t(y) * width + x]; }
};

// One view before and after hole filling: colour, the depth that landed (kHole where none did).
inline constexpr float kHole = -1.0f;
struct WarpedView {
  int width = 0, height = 0;
  ImageF colour;             // 3 channels, black at holes before fill_holes
  std::vector<float> depth;  // kHole at holes
  float depth_at(int x, int y) const { return depth[size_t(y) * width + x]; }
};

// Stage 1. `frame`: the side-by-side image (top-down, 3 or 4 channels in [0, 1]). Output tile
// pixel (x, y) samples the frame's halves at the source position of docs/rgbd.md "Zoom and crop".
RgbdSource resample_rgbd(const ImageF& frame, const RgbdOptions& options, int tile_width,
                         int tile_height);
// Stage 2, for a view whose shift per unit z-ratio is `shift_px_per_z_ratio`.
WarpedView warp_view(const RgbdSource& source, const RgbdOptions& options,
                     float shift_px_per_z_ratio);
// Stage 3, in place; returns the number of pixels filled.
size_t fill_holes(WarpedView& view);

// The whole quilt (top-down, 3 channels, layout.width x layout.height; view j in its tile per
// render::QuiltLayout, black outside the tiles). Checks options and layout (InputError naming the
// field), and the frame (InputError "RGB-D frame: ..." when empty or too small to split).
ImageF render_rgbd_quilt(const ImageF& frame, const RgbdOptions& options,
                         const render::QuiltLayout& layout,
                         double view_cone_deg = kDefaultViewConeDeg);

}  // namespace lfd::rgbd
