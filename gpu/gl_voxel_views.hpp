#pragma once
// Per-view voxel quilts on the GPU (issue #13): the GL twin of voxel/voxel_quilt.hpp. Every
// view rendered alone through its off-axis camera at ss times its size (GlVoxelRaster into an
// RGBA32F (C, T) target, the background composited), then downsampled with SVRaster's
// antialiasing filter (gpu/shaders/voxel_downsample.comp.glsl) straight into its quilt tile,
// cropped as render::place_view crops. The ground truth V2LF is measured against on the GPU.
// RasterPath::kCompute draws with the compute tile rasterizer (GlVoxelTileRaster) instead of the
// raster pipeline (docs/gpu.md "Voxels on the GPU").
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "gpu/gl_objects.hpp"
#include "gpu/gl_splat_raster.hpp"
#include "gpu/gl_voxel_raster.hpp"
#include "gpu/gl_voxel_scene.hpp"
#include "gpu/gl_voxel_tile_raster.hpp"
#include "gpu/raster_path.hpp"
#include "render/blend.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"
#include "voxel/voxel_rasterizer.hpp"

namespace lfd::gpu {

class GlVoxelViews {
 public:
  // Needs a current context; `scene` outlives this. `raster`: hardware or compute (auto is the
  // caller's to resolve: gpu::resolve_raster_path).
  explicit GlVoxelViews(const GlVoxelScene& scene, RasterPath raster = RasterPath::kHardware);

  // Every view of `geometry` into its tile of `quilt` (GL_RGBA8, GL_RGBA16F or GL_RGBA32F of the
  // layout's size; rows bottom-up, view 0 bottom-left); texels outside the tiles are cleared to 0.
  void render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                    const voxel::VoxelRenderSettings& settings, const Texture& quilt);
  // One view through `camera`: the CPU's rasterize_voxels (rgb and transmittance).
  render::RasterImage render_view(const render::Camera& camera, const voxel::VoxelRenderSettings& settings);

 private:
  // Renders at ss times `camera`'s size and downsamples into `target` at `view_origin`,
  // writing only `write_region` (x, y, w, h); alpha T or 1.
  void render_into(const render::Camera& camera, const voxel::VoxelRenderSettings& settings, const Texture& target,
                   glm::ivec2 view_origin, glm::ivec4 write_region, bool keep_transmittance);
  const Program& downsample(GLenum format);

  const GlVoxelScene& scene_;
  GlVoxelRaster raster_;
  std::unique_ptr<GlVoxelTileRaster> tile_raster_;  // RasterPath::kCompute
  GlSplatRaster targets_;  // clear and background composite of (C, T) targets
  Texture supersampled_;
  Framebuffer supersampled_framebuffer_;
  Program downsample_rgba8_, downsample_rgba16f_, downsample_rgba32f_;
};

// One-off renders on the GPU of the current context (upload, render, read back): the CPU's
// render_voxel_quilt_per_view (RGB, rows top-down) and render_voxel_view.
ImageF render_voxel_quilt_per_view_gl(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                                      const render::QuiltLayout& layout,
                                      const voxel::VoxelRenderSettings& settings = {},
                                      RasterPath raster = RasterPath::kHardware);
render::RasterImage render_voxel_view_gl(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                                         int view, const voxel::VoxelRenderSettings& settings = {},
                                         RasterPath raster = RasterPath::kHardware);

}  // namespace lfd::gpu
