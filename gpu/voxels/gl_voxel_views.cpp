#include "gpu/voxels/gl_voxel_views.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_limits.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/gl/gl_quilt_target.hpp"
#include "gpu/planes/shaders/plane_io.h"
#include "gpu/voxels/shaders/voxel_downsample.comp.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

Program make_downsample(const char* format) {
  return Program(std::string("voxel downsample into ") + format,
                 {{GL_COMPUTE_SHADER, voxel_downsample_comp_glsl}}, {std::string("OUT_FORMAT ") + format},
                 {texture("source", kDownsampleSourceUnit), image("target", kDownsampleTargetImage, Access::write)});
}

// voxel::rasterize_voxels' supersampling: the scene's ss unless the settings say.
float supersampling_of(const scene::VoxelScene& scene, const voxel::VoxelRenderSettings& settings) {
  const float ss = settings.supersampling.value_or(scene.supersampling);
  if (!(ss >= 1.0f && ss <= 4.0f)) throw_input_error("voxel rasterizer: supersampling {} must lie in [1, 4]", ss);
  return ss;
}

}  // namespace

GlVoxelViews::GlVoxelViews(const GlVoxelScene& scene, RasterPath raster)
    : scene_(scene),
      tile_raster_(raster == RasterPath::kCompute ? std::make_unique<GlVoxelTileRaster>() : nullptr),
      downsample_rgba8_(make_downsample("rgba8")),
      downsample_rgba16f_(make_downsample("rgba16f")),
      downsample_rgba32f_(make_downsample("rgba32f")) {
  if (raster == RasterPath::kAuto) throw std::logic_error("GlVoxelViews: resolve the raster path before (auto)");
}

void GlVoxelViews::set_pass_limit(size_t bytes) {
  pass_limit_ = bytes;
  if (tile_raster_) tile_raster_->set_pass_limit(bytes);
}

const Program& GlVoxelViews::downsample_program(GLenum format) {
  switch (format) {
    case GL_RGBA8: return downsample_rgba8_;
    case GL_RGBA16F: return downsample_rgba16f_;
    case GL_RGBA32F: return downsample_rgba32f_;
    default: throw_input_error("voxel views: the target must be GL_RGBA8, GL_RGBA16F or GL_RGBA32F");
  }
}

const Texture& GlVoxelViews::supersampled(glm::ivec2 size) {
  if (!supersampled_.id() || supersampled_.width() != size.x || supersampled_.height() != size.y) {
    supersampled_ = Texture(GL_RGBA32F, size.x, size.y);
    supersampled_framebuffer_.attach(0, supersampled_);
    supersampled_framebuffer_.finish(1);
  }
  return supersampled_;
}

void GlVoxelViews::downsample(const Texture& source, glm::ivec2 source_size, int source_cols, glm::ivec2 view_size,
                              int first_view, int count, const ViewTiles& tiles, const glm::vec3* add_background) {
  const Program& program = downsample_program(tiles.target->internal_format());
  const GLuint p = program.id();
  glProgramUniform2i(p, program.uniform("source_size"), source_size.x, source_size.y);
  glProgramUniform1i(p, program.uniform("source_cols"), source_cols);
  glProgramUniform2i(p, program.uniform("view_size"), view_size.x, view_size.y);
  glProgramUniform1i(p, program.uniform("first_view"), first_view);
  glProgramUniform1i(p, program.uniform("target_cols"), tiles.cols);
  glProgramUniform2i(p, program.uniform("tile_size"), tiles.tile_size.x, tiles.tile_size.y);
  glProgramUniform1i(p, program.uniform("add_background"), add_background ? 1 : 0);
  if (add_background) glProgramUniform3fv(p, program.uniform("background"), 1, glm::value_ptr(*add_background));
  glProgramUniform1f(p, program.uniform("alpha_out"), tiles.alpha == TargetAlpha::kTransmittance ? -1.0f : 1.0f);
  program.bind("source", source);
  program.bind("target", *tiles.target);
  program.use();
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the passes before wrote what this one reads
  program.dispatch((GLuint(view_size.x) + kPlaneGroupWidth - 1) / kPlaneGroupWidth,
                   (GLuint(view_size.y) + kPlaneGroupHeight - 1) / kPlaneGroupHeight, GLuint(count));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  glBindTextureUnit(kDownsampleSourceUnit, 0);
  check_gl("downsampling voxel views");
}

void GlVoxelViews::render_views(std::span<const render::Camera> cameras, const voxel::VoxelRenderSettings& settings,
                                const ViewTiles& tiles) {
  const scene::VoxelScene& scene = scene_.scene();
  const float ss = supersampling_of(scene, settings);
  std::vector<render::Camera> big(cameras.begin(), cameras.end());  // the same frusta: fov and shift are in NDC
  for (render::Camera& c : big) {
    c.width = std::max(1, int(std::lround(ss * float(c.width))));
    c.height = std::max(1, int(std::lround(ss * float(c.height))));
  }
  atlas_groups_ = passes_ = 0;
  if (cameras.empty()) return;
  for (const render::Camera& c : cameras)
    if (c.width != cameras[0].width || c.height != cameras[0].height)
      throw std::invalid_argument("voxel views: views of different sizes");
  if (tile_raster_) return render_views_compute(big, {cameras[0].width, cameras[0].height}, settings, tiles);
  const glm::vec3 background = settings.background.value_or(scene.background);
  for (size_t view = 0; view < big.size(); ++view) {
    const glm::ivec2 size(big[view].width, big[view].height);
    supersampled(size);
    SplatRasterTarget hi;
    hi.framebuffer = supersampled_framebuffer_.id();
    hi.image_size = size;
    targets_.clear(hi);
    raster_.draw(scene_, big[view], big[view].position_world, hi);
    targets_.composite_background(hi, background, TargetAlpha::kTransmittance);
    downsample(supersampled_, size, 1, {cameras[view].width, cameras[view].height}, int(view), 1, tiles, nullptr);
  }
}

void GlVoxelViews::render_views_compute(std::span<const render::Camera> big, glm::ivec2 view_size,
                                        const voxel::VoxelRenderSettings& settings, const ViewTiles& tiles) {
  // Groups of views whose atlas fits the largest texture and the pass limit's bytes (one group
  // unless the quilt is huge); each group: one clear, one tile pass (GlVoxelTileRaster splits it
  // further only when its buffers would not fit), one downsample.
  const glm::ivec2 cell(big[0].width, big[0].height);
  const int max_texture = gl_limits().texture_size;
  const int max_cols = max_texture / cell.x, max_rows = max_texture / cell.y;
  if (max_cols < 1 || max_rows < 1)
    throw_input_error("--raster compute: a supersampled {}x{} view exceeds the GPU's largest texture ({})", cell.x,
                      cell.y, max_texture);
  const size_t limit = tile_raster_->pass_limit();
  const size_t cell_bytes = size_t(cell.x) * size_t(cell.y) * 16;
  const size_t per_group = std::min({big.size(), size_t(max_cols) * size_t(max_rows), std::max<size_t>(1, limit / cell_bytes)});
  const int cols = int(std::min<size_t>(per_group, size_t(max_cols)));
  const int rows = int((per_group + size_t(cols) - 1) / size_t(cols));
  const Texture& atlas = supersampled(cell * glm::ivec2(cols, rows));
  const glm::vec3 background = settings.background.value_or(scene_.scene().background);
  const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // (C, T) before any voxel
  for (size_t first = 0; first < big.size(); first += per_group) {
    const size_t count = std::min(per_group, big.size() - first);
    glClearTexImage(atlas.id(), 0, GL_RGBA, GL_FLOAT, empty);
    tile_raster_->render_views(scene_, big.subspan(first, count), atlas, cols);
    passes_ += tile_raster_->passes();
    ++atlas_groups_;
    downsample(atlas, cell, cols, view_size, int(first), int(count), tiles, &background);
  }
}

void GlVoxelViews::render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                const voxel::VoxelRenderSettings& settings, const Texture& quilt) {
  check_quilt_target("voxel views", geometry, layout, quilt);
  const float outside[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // as the CPU's quilt outside the tiles
  glClearTexImage(quilt.id(), 0, GL_RGBA, GL_FLOAT, outside);
  std::vector<render::Camera> cameras;
  for (int view = 0; view < geometry.views; ++view) cameras.push_back(geometry.view_camera(view));
  render_views(cameras, settings,
               {.target = &quilt, .cols = layout.cols, .tile_size = {layout.tile_width(), layout.tile_height()},
                .alpha = TargetAlpha::kOpaque});
}

render::RasterImage GlVoxelViews::render_view(const render::Camera& camera, const voxel::VoxelRenderSettings& settings) {
  const Texture image(GL_RGBA32F, camera.width, camera.height);
  render_views({&camera, 1}, settings,
               {.target = &image, .cols = 1, .tile_size = {camera.width, camera.height},
                .alpha = TargetAlpha::kTransmittance});
  const ImageF rgba = read_image_top_down(image, 4);
  render::RasterImage out;
  out.width = rgba.width;
  out.height = rgba.height;
  out.rgb.resize(size_t(rgba.width) * size_t(rgba.height) * 3);
  out.transmittance.resize(size_t(rgba.width) * size_t(rgba.height));
  for (size_t p = 0; p < out.transmittance.size(); ++p) {
    for (size_t c = 0; c < 3; ++c) out.rgb[3 * p + c] = rgba.pixels[4 * p + c];
    out.transmittance[p] = rgba.pixels[4 * p + 3];
  }
  return out;
}

ImageF render_voxel_quilt_per_view_gl(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                                      const render::QuiltLayout& layout, const voxel::VoxelRenderSettings& settings,
                                      RasterPath raster) {
  const GlVoxelScene gl_scene(scene, query_gl_info("current context"));
  GlVoxelViews views(gl_scene, raster);
  const Texture quilt(GL_RGBA32F, layout.width, layout.height);
  views.render_quilt(geometry, layout, settings, quilt);
  return read_image_top_down(quilt, 3);
}

render::RasterImage render_voxel_view_gl(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                                         int view, const voxel::VoxelRenderSettings& settings,
                                         RasterPath raster) {
  if (view < 0 || view >= geometry.views) throw_input_error("view {} is outside 0..{}", view, geometry.views - 1);
  const GlVoxelScene gl_scene(scene, query_gl_info("current context"));
  GlVoxelViews views(gl_scene, raster);
  return views.render_view(geometry.view_camera(view), settings);
}

}  // namespace lfd::gpu
