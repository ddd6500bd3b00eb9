#include "gpu/gl_voxel_views.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "gpu/gl_context.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_quilt_target.hpp"
#include "gpu/shaders/plane_io.h"
#include "gpu/shaders/voxel_downsample.comp.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

Program downsample_program(const char* format) {
  return Program(std::string("voxel downsample into ") + format,
                 {{GL_COMPUTE_SHADER, voxel_downsample_comp_glsl}}, {std::string("OUT_FORMAT ") + format});
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
      downsample_rgba8_(downsample_program("rgba8")),
      downsample_rgba16f_(downsample_program("rgba16f")),
      downsample_rgba32f_(downsample_program("rgba32f")) {
  if (raster == RasterPath::kAuto) throw std::logic_error("GlVoxelViews: resolve the raster path before (auto)");
}

const Program& GlVoxelViews::downsample(GLenum format) {
  switch (format) {
    case GL_RGBA8: return downsample_rgba8_;
    case GL_RGBA16F: return downsample_rgba16f_;
    case GL_RGBA32F: return downsample_rgba32f_;
    default: throw_input_error("voxel views: the target must be GL_RGBA8, GL_RGBA16F or GL_RGBA32F");
  }
}

void GlVoxelViews::render_into(const render::Camera& camera, const voxel::VoxelRenderSettings& settings,
                               const Texture& target, glm::ivec2 view_origin, glm::ivec4 write_region,
                               bool keep_transmittance) {
  const scene::VoxelScene& scene = scene_.scene();
  const float ss = supersampling_of(scene, settings);
  render::Camera big = camera;  // the same frustum: fov and principal-point shift are in NDC
  big.width = std::max(1, int(std::lround(ss * float(camera.width))));
  big.height = std::max(1, int(std::lround(ss * float(camera.height))));
  if (!supersampled_.id() || supersampled_.width() != big.width || supersampled_.height() != big.height) {
    supersampled_ = Texture(GL_RGBA32F, big.width, big.height);
    supersampled_framebuffer_.attach(0, supersampled_);
    supersampled_framebuffer_.finish(1);
  }
  SplatRasterTarget hi;
  hi.framebuffer = supersampled_framebuffer_.id();
  hi.image_size = {big.width, big.height};
  targets_.clear(hi);
  if (tile_raster_)
    tile_raster_->draw(scene_, big, big.position_world, supersampled_, glm::ivec2(0));
  else
    raster_.draw(scene_, big, big.position_world, hi);
  targets_.composite_background(hi, settings.background.value_or(scene.background), /*keep_transmittance=*/true);

  const Program& program = downsample(target.internal_format());
  const GLuint p = program.id();
  glProgramUniform2i(p, program.uniform("source_size"), big.width, big.height);
  glProgramUniform2i(p, program.uniform("view_size"), camera.width, camera.height);
  glProgramUniform2i(p, program.uniform("view_origin"), view_origin.x, view_origin.y);
  glProgramUniform4i(p, program.uniform("write_region"), write_region.x, write_region.y, write_region.z,
                     write_region.w);
  glProgramUniform1f(p, program.uniform("alpha_out"), keep_transmittance ? -1.0f : 1.0f);
  glBindTextureUnit(kDownsampleSourceUnit, supersampled_.id());
  glBindImageTexture(kDownsampleTargetImage, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, target.internal_format());
  program.use();
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);  // the draws above wrote what the pass reads
  glDispatchCompute((GLuint(camera.width) + kPlaneGroupWidth - 1) / kPlaneGroupWidth,
                    (GLuint(camera.height) + kPlaneGroupHeight - 1) / kPlaneGroupHeight, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  glBindTextureUnit(kDownsampleSourceUnit, 0);
  check_gl("downsampling a voxel view");
}

void GlVoxelViews::render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                const voxel::VoxelRenderSettings& settings, const Texture& quilt) {
  check_quilt_target("voxel views", geometry, layout, quilt);
  const float outside[4] = {0.0f, 0.0f, 0.0f, 1.0f};  // as the CPU's quilt outside the tiles
  glClearTexImage(quilt.id(), 0, GL_RGBA, GL_FLOAT, outside);
  const int W = geometry.base.width, H = geometry.base.height;
  const int tile_w = layout.tile_width(), tile_h = layout.tile_height();
  for (int view = 0; view < geometry.views; ++view) {
    // The tile in GL texel coordinates (bottom-up: tile row r starts at r * tile_h); the view's
    // top row lands on the tile's top row, a view larger than the tile is cropped at its right
    // and bottom (render::place_view).
    const int x0 = layout.tile_x(view), y0 = (view / layout.cols) * tile_h;
    const glm::ivec2 origin(x0, y0 + tile_h - H);
    const glm::ivec4 region(x0, y0 + tile_h - std::min(tile_h, H), std::min(tile_w, W), std::min(tile_h, H));
    render_into(geometry.view_camera(view), settings, quilt, origin, region, /*keep_transmittance=*/false);
  }
}

render::RasterImage GlVoxelViews::render_view(const render::Camera& camera, const voxel::VoxelRenderSettings& settings) {
  const Texture image(GL_RGBA32F, camera.width, camera.height);
  render_into(camera, settings, image, glm::ivec2(0), glm::ivec4(0, 0, camera.width, camera.height),
              /*keep_transmittance=*/true);
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
