#include "rgbd/rgbd_view_model.hpp"

#include <cmath>
#include <numbers>

#include "display/display_quilt.hpp"
#include "render/camera.hpp"
#include "render/default_camera.hpp"
#include "rgbd/rgbd_frame.hpp"
#include "util/error.hpp"

namespace lfd::rgbd {

render::QuiltGeometry rgbd_quilt_geometry(const render::QuiltLayout& layout, double view_cone_deg) {
  layout.check("RGB-D quilt");
  const float fov_y = render::kDefaultFovYDeg * std::numbers::pi_v<float> / 180.0f;
  const render::Camera base = render::make_look_at_camera(
      glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, -1.0f, 0.0f), fov_y,
      layout.tile_width(), layout.tile_height());
  return render::make_quilt_geometry(base, 1.0f, float(view_cone_deg), layout.views);
}

float relief_z_ratio(float depth, const RgbdOptions& options) {
  return float(options.depthiness * kReliefRatio) * (0.5f - depth) + float(options.focus);
}

double zero_parallax_depth(const RgbdOptions& options) {
  return 0.5 + options.focus / (options.depthiness * kReliefRatio);
}

float view_shift_px_per_z_ratio(const render::QuiltGeometry& geometry, int view, int tile_width) {
  return geometry.view_shift_ndc(view) * 0.5f * float(tile_width);
}

float view_shift_px(const render::QuiltGeometry& geometry, int view, int tile_width, float depth,
                    const RgbdOptions& options) {
  return view_shift_px_per_z_ratio(geometry, view, tile_width) * relief_z_ratio(depth, options);
}

render::QuiltLayout rgbd_quilt_layout(int frame_width, int frame_height, DepthLocation location,
                                      int views, int tile_height) {
  const RgbdSplit split = split_rgbd_frame(frame_width, frame_height, location);
  if (tile_height < 0) throw_input_error("RGB-D quilt: tile height {} must be positive", tile_height);
  const double aspect = split.colour_aspect();
  const display::QuiltGrid grid = display::quilt_grid_for_views(views, aspect);
  const int th = tile_height > 0 ? tile_height : split.colour.height;
  const int tw = std::max(1, int(std::lround(th * aspect)));
  render::QuiltLayout layout;
  layout.cols = grid.cols;
  layout.rows = grid.rows;
  layout.views = views;
  layout.aspect = aspect;
  layout.width = tw * grid.cols;
  layout.height = th * grid.rows;
  layout.check("RGB-D quilt");
  return layout;
}

}  // namespace lfd::rgbd
