#pragma once
// Per-view voxel quilts on the GPU (docs/gpu.md "Voxels on the GPU"): the GL twin of voxel/voxel_quilt.hpp. Every
// view rendered alone through its off-axis camera at ss times its size (GlVoxelRaster into an
// RGBA32F (C, T) target, the background composited), then downsampled with SVRaster's
// antialiasing filter (gpu/voxels/shaders/voxel_downsample.comp.glsl) straight into its quilt tile,
// cropped as render::place_view crops. The ground truth V2LF is measured against on the GPU.
// RasterPath::kCompute draws with the compute tile rasterizer (GlVoxelTileRaster) instead of the
// raster pipeline, every view of a quilt at once: the supersampled views side by side in one
// RGBA32F atlas, one sort and one march for them all, one downsample dispatch (docs/gpu.md
// "Voxels on the GPU"); views go in groups only when the atlas would pass the GPU's largest
// texture or storage block.
#include <memory>
#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/gl_splat_raster.hpp"
#include "gpu/voxels/gl_voxel_raster.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "gpu/voxels/gl_voxel_tile_raster.hpp"
#include "gpu/gl/raster_path.hpp"
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

  // The compute path's bytes a pass may bind and the atlas may hold (GlVoxelTileRaster::
  // set_pass_limit; 0: the GPU's largest storage block). For the tests.
  void set_pass_limit(size_t bytes);
  // The compute path's groups of views (atlases) and tile passes in the last render.
  int atlas_groups() const { return atlas_groups_; }
  int passes() const { return passes_; }
  const GlVoxelTileRaster* tile_raster() const { return tile_raster_.get(); }

 private:
  // Where downsampled views go: view v into tile (v % cols, v / cols) of tile_size (bottom-up),
  // alpha T (TargetAlpha::kTransmittance) or 1 (kOpaque), as the Gaussians' TileViewsTarget.
  struct ViewTiles {
    const Texture* target = nullptr;
    int cols = 1;
    glm::ivec2 tile_size{0};
    TargetAlpha alpha = TargetAlpha::kOpaque;
  };
  // Every camera (views 0..) at ss times its size, composited over the background and
  // downsampled into its tile: per view through the raster pipeline, or all at once by the
  // compute tile rasterizer.
  void render_views(std::span<const render::Camera> cameras, const voxel::VoxelRenderSettings& settings,
                    const ViewTiles& tiles);
  void render_views_compute(std::span<const render::Camera> big, glm::ivec2 view_size,
                            const voxel::VoxelRenderSettings& settings, const ViewTiles& tiles);
  // Downsamples `count` supersampled views (cells of `source`, `source_cols` a row) into views
  // first_view.. of `tiles`; add_background: the source holds (C, T).
  void downsample(const Texture& source, glm::ivec2 source_size, int source_cols, glm::ivec2 view_size,
                  int first_view, int count, const ViewTiles& tiles, const glm::vec3* add_background);
  const Program& downsample_program(GLenum format);
  // The supersampled target (GL_RGBA32F) of at least `size`, made or grown as needed.
  const Texture& supersampled(glm::ivec2 size);

  const GlVoxelScene& scene_;
  GlVoxelRaster raster_;
  std::unique_ptr<GlVoxelTileRaster> tile_raster_;  // RasterPath::kCompute
  GlSplatRaster targets_;  // clear and background composite of (C, T) targets
  Texture supersampled_;
  Framebuffer supersampled_framebuffer_;
  Program downsample_rgba8_, downsample_rgba16f_, downsample_rgba32f_;
  size_t pass_limit_ = 0;
  int atlas_groups_ = 0;
  int passes_ = 0;
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
