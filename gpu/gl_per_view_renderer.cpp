#include "gpu/gl_per_view_renderer.hpp"

#include <algorithm>
#include <stdexcept>

#include "util/error.hpp"

namespace lfd::gpu {
namespace {

bool is_float_format(GLenum format) { return format == GL_RGBA16F || format == GL_RGBA32F; }

}  // namespace

GlPerViewRenderer::GlPerViewRenderer(const GlScene& scene, const GlPerViewOptions& options)
    : scene_(scene), options_(options) {
  if (!is_float_format(options_.accumulation_format))
    throw std::invalid_argument("per-view renderer: the accumulation target must be GL_RGBA16F or GL_RGBA32F");
}

GlPerViewRenderer::ViewTimers* GlPerViewRenderer::timers_for(int view) {
  if (!options_.gpu_timers) return nullptr;
  while (int(timers_.size()) <= view) timers_.emplace_back();
  return &timers_[size_t(view)];
}

void GlPerViewRenderer::prepare(const render::Camera& camera, const render::RasterSettings& settings,
                                ViewTimers* timers) {
  if (timers) timers->preprocess.begin();
  preprocess_.run(scene_, camera, settings, buffers_);
  if (timers) {
    timers->preprocess.end();
    timers->sort.begin();
  }
  sort_.sort(buffers_.keys, buffers_.values, uint32_t(scene_.size()));
  if (timers) timers->sort.end();
}

void GlPerViewRenderer::ensure_view_target(int width, int height) {
  if (view_target_.id() && view_target_.width() == width && view_target_.height() == height) return;
  view_target_ = Texture(options_.accumulation_format, width, height);
  view_framebuffer_.attach(0, view_target_);
  view_framebuffer_.finish(1);
}

void GlPerViewRenderer::finish_stats(int views) {
  stats_ = {};
  stats_.views = views;
  if (options_.gpu_timers)
    for (int v = 0; v < views; ++v) {
      stats_.preprocess_s += timers_[size_t(v)].preprocess.seconds();
      stats_.sort_s += timers_[size_t(v)].sort.seconds();
      stats_.raster_s += timers_[size_t(v)].raster.seconds();
    }
  stats_.memory_bytes = scene_.bytes() + buffers_.bytes() + sort_.scratch_bytes() + view_target_.bytes();
}

const Texture& GlPerViewRenderer::render_view(const render::Camera& camera, const render::RasterSettings& settings) {
  if (camera.width <= 0 || camera.height <= 0)
    throw_input_error("per-view renderer: image size {}x{} is not positive", camera.width, camera.height);
  ensure_view_target(camera.width, camera.height);
  ViewTimers* timers = timers_for(0);
  prepare(camera, settings, timers);
  SplatRasterTarget target;
  target.framebuffer = view_framebuffer_.id();
  target.image_size = {camera.width, camera.height};
  if (timers) timers->raster.begin();
  raster_.clear(target);
  raster_.draw(buffers_, target);
  raster_.composite_background(target, settings.background, /*keep_transmittance=*/true);
  if (timers) timers->raster.end();
  finish_stats(1);
  return view_target_;
}

render::RasterImage GlPerViewRenderer::render_view_image(const render::Camera& camera,
                                                         const render::RasterSettings& settings) {
  const ImageF rgba = read_image_top_down(render_view(camera, settings), 4);
  render::RasterImage image;
  image.width = rgba.width;
  image.height = rgba.height;
  image.rgb.resize(size_t(rgba.width) * rgba.height * 3);
  image.transmittance.resize(size_t(rgba.width) * rgba.height);
  for (size_t p = 0; p < image.transmittance.size(); ++p) {
    for (int c = 0; c < 3; ++c) image.rgb[3 * p + size_t(c)] = rgba.pixels[4 * p + size_t(c)];
    image.transmittance[p] = rgba.pixels[4 * p + 3];
  }
  return image;
}

void GlPerViewRenderer::render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                     const render::RasterSettings& settings, Texture& quilt) {
  layout.check("quilt");
  if (quilt.width() != layout.width || quilt.height() != layout.height || quilt.layers() != 0)
    throw_input_error("per-view renderer: the quilt texture is {}x{}, the layout {}x{}", quilt.width(),
                      quilt.height(), layout.width, layout.height);
  if (geometry.views > layout.views)
    throw_input_error("per-view renderer: {} views do not fit a quilt of {}", geometry.views, layout.views);
  const bool direct = is_float_format(quilt.internal_format());
  const int W = geometry.base.width, H = geometry.base.height;
  if (!direct) ensure_view_target(W, H);

  Framebuffer quilt_framebuffer;
  quilt_framebuffer.attach(0, quilt);
  quilt_framebuffer.finish(1);
  const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glClearNamedFramebufferfv(quilt_framebuffer.id(), GL_COLOR, 0, empty);

  const int tile_w = layout.tile_width(), tile_h = layout.tile_height();
  for (int view = 0; view < geometry.views; ++view) {
    ViewTimers* timers = timers_for(view);
    prepare(geometry.view_camera(view), settings, timers);
    // The tile in GL window coordinates (bottom-up: tile row r starts at r * tile_h). The view's
    // top row goes to the tile's top row and a view larger than the tile is cropped at its
    // right and bottom, as render::place_view copies it.
    const int x0 = layout.tile_x(view), y0 = (view / layout.cols) * tile_h;
    SplatRasterTarget tile;
    tile.framebuffer = quilt_framebuffer.id();
    tile.image_size = {W, H};
    tile.viewport_origin = {x0, y0 + tile_h - H};
    tile.scissor = {x0, y0 + tile_h - std::min(tile_h, H), std::min(tile_w, W), std::min(tile_h, H)};
    if (timers) timers->raster.begin();
    if (direct) {
      raster_.clear(tile);
      raster_.draw(buffers_, tile);
      raster_.composite_background(tile, settings.background, /*keep_transmittance=*/false);
    } else {
      SplatRasterTarget view_target;
      view_target.framebuffer = view_framebuffer_.id();
      view_target.image_size = {W, H};
      raster_.clear(view_target);
      raster_.draw(buffers_, view_target);
      raster_.composite_from(view_target_, tile, settings.background);
    }
    if (timers) timers->raster.end();
  }
  finish_stats(geometry.views);
}

ImageF read_image_top_down(const Texture& texture, int channels) {
  const std::vector<float> rgba = read_texture_rgba(texture);
  const int w = texture.width(), h = texture.height();
  ImageF image(w, h, channels);
  for (int y = 0; y < h; ++y) {
    const float* row = rgba.data() + size_t(h - 1 - y) * w * 4;
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) image.at(x, y, c) = row[4 * x + c];
  }
  return image;
}

}  // namespace lfd::gpu
