#include "render/per_view_quilt.hpp"

#include "util/error.hpp"
#include "util/progress.hpp"

namespace lfd::render {

QuiltLayout make_quilt_layout(const QuiltGeometry& geometry, int cols, int rows) {
  QuiltLayout q;
  q.cols = cols;
  q.rows = rows;
  q.views = geometry.views;
  q.aspect = double(geometry.base.width) / double(geometry.base.height);
  q.width = cols * geometry.base.width;
  q.height = rows * geometry.base.height;
  q.check("quilt");
  return q;
}

void place_view(ImageF& quilt, const QuiltLayout& layout, int view, const RasterImage& image) {
  const int x0 = layout.tile_x(view), y0 = layout.tile_y_top_down(view);
  const int w = std::min(image.width, layout.tile_width()), h = std::min(image.height, layout.tile_height());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        quilt.at(x0 + x, y0 + y, c) = image.rgb[(size_t(y) * image.width + x) * 3 + c];
}

ImageF extract_view(const ImageF& quilt, const QuiltLayout& layout, int view) {
  ImageF out(layout.tile_width(), layout.tile_height(), quilt.channels);
  const int x0 = layout.tile_x(view), y0 = layout.tile_y_top_down(view);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < quilt.channels; ++c) out.at(x, y, c) = quilt.at(x0 + x, y0 + y, c);
  return out;
}

RasterImage render_view(const scene::GaussianScene& scene, const QuiltGeometry& geometry, int view,
                        const RasterSettings& settings) {
  if (view < 0 || view >= geometry.views)
    throw_input_error("view {} is outside 0..{}", view, geometry.views - 1);
  return rasterize(scene, geometry.view_camera(view), settings);
}

ImageF render_quilt_per_view(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                             const QuiltLayout& layout, const RasterSettings& settings) {
  ImageF quilt(layout.width, layout.height, 3, 0.0f);
  Progress progress("per-view quilt", geometry.views);
  for (int j = 0; j < geometry.views; ++j) {
    place_view(quilt, layout, j, render_view(scene, geometry, j, settings));
    progress.advance();
  }
  progress.finish();
  return quilt;
}

ImageF render_quilt_per_view_masked(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                                    const QuiltLayout& layout,
                                    const std::vector<std::vector<uint8_t>>& pixel_masks,
                                    const RasterSettings& settings) {
  if (pixel_masks.size() != size_t(geometry.views))
    throw_input_error("per-view masks: {} masks for {} views", pixel_masks.size(), geometry.views);
  ImageF quilt(layout.width, layout.height, 3, 0.0f);
  for (int j = 0; j < geometry.views; ++j) {
    const Camera camera = geometry.view_camera(j);
    if (pixel_masks[size_t(j)].size() != size_t(camera.width) * camera.height)
      throw_input_error("per-view masks: mask {} has {} pixels, the view {}x{}", j, pixel_masks[size_t(j)].size(),
                        camera.width, camera.height);
    place_view(quilt, layout, j, rasterize_masked(scene, camera, pixel_masks[size_t(j)], settings));
  }
  return quilt;
}

}  // namespace lfd::render
