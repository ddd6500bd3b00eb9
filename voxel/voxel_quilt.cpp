#include "voxel/voxel_quilt.hpp"

#include "util/error.hpp"
#include "util/progress.hpp"

namespace lfd::voxel {

render::RasterImage render_voxel_view(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry, int view,
                                      const VoxelRenderSettings& settings) {
  if (view < 0 || view >= geometry.views)
    throw_input_error("view {} is outside 0..{}", view, geometry.views - 1);
  return rasterize_voxels(scene, geometry.view_camera(view), settings);
}

ImageF render_voxel_quilt_per_view(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                                   const render::QuiltLayout& layout, const VoxelRenderSettings& settings) {
  ImageF quilt(layout.width, layout.height, 3, 0.0f);
  Progress progress("per-view voxel quilt", geometry.views);
  for (int j = 0; j < geometry.views; ++j) {
    render::place_view(quilt, layout, j, render_voxel_view(scene, geometry, j, settings));
    progress.advance();
  }
  progress.finish();
  return quilt;
}

}  // namespace lfd::voxel
