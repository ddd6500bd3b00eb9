#pragma once
// Per-view voxel quilts: every view rendered alone by the exact voxel rasterizer through its
// off-axis camera (render/quilt_geometry.hpp), placed in the same quilt layout as Gaussian
// quilts. The ground truth for V2LF, as SVR quilts are in the paper's Table 1.
#include "render/per_view_quilt.hpp"
#include "voxel/voxel_rasterizer.hpp"

namespace lfd::voxel {

render::RasterImage render_voxel_view(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry, int view,
                                      const VoxelRenderSettings& settings = {});

ImageF render_voxel_quilt_per_view(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                                   const render::QuiltLayout& layout, const VoxelRenderSettings& settings = {});

}  // namespace lfd::voxel
