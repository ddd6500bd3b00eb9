#include "gpu/splats/gl_per_view_renderer.hpp"

#include <algorithm>
#include <stdexcept>

#include "gpu/gl/gl_quilt_target.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

bool is_float_format(GLenum format) { return format == GL_RGBA16F || format == GL_RGBA32F; }

}  // namespace

GlPerViewRenderer::GlPerViewRenderer(const GlScene& scene, const GlPerViewOptions& options)
    : scene_(scene), options_(options) {
  if (!is_float_format(options_.accumulation_format))
    throw std::invalid_argument("per-view renderer: the accumulation target must be GL_RGBA16F or GL_RGBA32F");
  if (options_.depth_key_bits % 8 != 0 || options_.depth_key_bits < 8 || options_.depth_key_bits > 32)
    throw std::invalid_argument("per-view renderer: depth_key_bits must be 8, 16, 24 or 32");
  if (options_.normalised_depth_keys && (options_.depth_key_bits > 24 || !options_.sort_visible_only))
    throw std::invalid_argument("per-view renderer: normalised depth keys need 8, 16 or 24 bits and sort_visible_only");
  if (options_.raster == RasterPath::kAuto)
    throw std::invalid_argument("per-view renderer: resolve --raster auto before making the renderer");
  if (options_.raster == RasterPath::kCompute) {
    tiles_ = std::make_unique<GlSplatTileRaster>();
    tiles_->set_pass_limit(options_.compute_pass_limit);
    tiles_->set_split_keys(options_.compute_split_keys);
  }
}

void GlPerViewRenderer::begin_timing(int views) {
  if (!options_.gpu_timers) return;
  const size_t stamps = 4 * size_t(views);
  if (!timers_ || timers_->stamps() != stamps) timers_.emplace(stamps, 0);
  timers_->begin_frame();
}

void GlPerViewRenderer::stamp(size_t index) {
  if (options_.gpu_timers) timers_->stamp(index);
}

GLuint GlPerViewRenderer::quilt_framebuffer(const Texture& quilt) {
  // Attached every frame (a deleted texture's name may come back as another texture), made once.
  quilt_framebuffer_.attach(0, quilt);
  quilt_framebuffer_.finish(1);
  return quilt_framebuffer_.id();
}

void GlPerViewRenderer::prepare(const render::Camera& camera, const render::RasterSettings& settings, int view) {
  stamp(4 * size_t(view));
  preprocess_.run(scene_, camera, settings, buffers_);
  stamp(4 * size_t(view) + 1);
  SortKeys how;
  how.low_bit = 32 - options_.depth_key_bits;
  how.drop_culled = options_.sort_visible_only;
  if (options_.normalised_depth_keys) {
    how.normalise_bits = options_.depth_key_bits;
    how.key_range = &buffers_.depth_range;
  }
  sort_.sort(buffers_.keys, buffers_.values, uint32_t(scene_.size()), how);
  stamp(4 * size_t(view) + 2);
}

void GlPerViewRenderer::ensure_view_target(int width, int height) {
  if (view_target_.id() && view_target_.width() == width && view_target_.height() == height) return;
  view_target_ = Texture(options_.accumulation_format, width, height);
  view_framebuffer_.attach(0, view_target_);
  view_framebuffer_.finish(1);
}

void GlPerViewRenderer::finish_stats(int views, int timed) {
  const GlPerViewStats last = stats_;
  stats_ = {};
  stats_.views = views;
  if (options_.gpu_timers) {
    timers_->end_frame();
    const std::optional<GlFrameReadout> frame =
        options_.timer_reads == TimerReads::kWait ? timers_->wait_newest() : timers_->newest_ready();
    if (frame) {
      for (size_t v = 0; v < size_t(timed); ++v) {
        stats_.preprocess_s += frame->seconds(4 * v, 4 * v + 1);
        stats_.sort_s += frame->seconds(4 * v + 1, 4 * v + 2);
        stats_.raster_s += frame->seconds(4 * v + 2, 4 * v + 3);
      }
    } else {  // kLate and no frame finished yet: the last figures stay
      stats_.preprocess_s = last.preprocess_s;
      stats_.sort_s = last.sort_s;
      stats_.raster_s = last.raster_s;
    }
  }
  stats_.memory_bytes = scene_.bytes() + buffers_.bytes() + sort_.scratch_bytes() + view_target_.bytes() +
                        (tiles_ ? tiles_->bytes() : 0);
}

const Texture& GlPerViewRenderer::render_view(const render::Camera& camera, const render::RasterSettings& settings) {
  if (camera.width <= 0 || camera.height <= 0)
    throw_input_error("per-view renderer: image size {}x{} is not positive", camera.width, camera.height);
  ensure_view_target(camera.width, camera.height);
  if (tiles_) {
    render_compute(std::span(&camera, 1), settings,
                   {.texture = &view_target_, .cols = 1, .cell_size = {camera.width, camera.height},
                    .background = settings.background, .alpha = TargetAlpha::kTransmittance});
    finish_stats(1, 1);
    return view_target_;
  }
  begin_timing(1);
  prepare(camera, settings, 0);
  SplatRasterTarget target;
  target.framebuffer = view_framebuffer_.id();
  target.image_size = {camera.width, camera.height};
  raster_.clear(target);
  raster_.draw(buffers_, target);
  raster_.composite_background(target, settings.background, TargetAlpha::kTransmittance);
  stamp(3);
  finish_stats(1, 1);
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
  check_quilt_target("per-view renderer", geometry, layout, quilt);
  if (tiles_) {
    const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glClearTexImage(quilt.id(), 0, GL_RGBA, GL_FLOAT, empty);
    std::vector<render::Camera> cameras;
    for (int view = 0; view < geometry.views; ++view) cameras.push_back(geometry.view_camera(view));
    render_compute(cameras, settings,
                   {.texture = &quilt, .cols = layout.cols, .cell_size = {layout.tile_width(), layout.tile_height()},
                    .background = settings.background, .alpha = TargetAlpha::kOpaque});
    finish_stats(geometry.views, 1);
    return;
  }
  const bool direct = is_float_format(quilt.internal_format());
  const int W = geometry.base.width, H = geometry.base.height;
  if (!direct) ensure_view_target(W, H);

  const GLuint framebuffer = quilt_framebuffer(quilt);
  const float empty[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, empty);
  begin_timing(geometry.views);

  const int tile_w = layout.tile_width(), tile_h = layout.tile_height();
  for (int view = 0; view < geometry.views; ++view) {
    prepare(geometry.view_camera(view), settings, view);
    // The tile in GL window coordinates (bottom-up: tile row r starts at r * tile_h). The view's
    // top row goes to the tile's top row and a view larger than the tile is cropped at its
    // right and bottom, as render::place_view copies it.
    const int x0 = layout.tile_x(view), y0 = (view / layout.cols) * tile_h;
    SplatRasterTarget tile;
    tile.framebuffer = framebuffer;
    tile.image_size = {W, H};
    tile.viewport_origin = {x0, y0 + tile_h - H};
    tile.scissor = {x0, y0 + tile_h - std::min(tile_h, H), std::min(tile_w, W), std::min(tile_h, H)};
    if (direct) {
      raster_.clear(tile);
      raster_.draw(buffers_, tile);
      raster_.composite_background(tile, settings.background, TargetAlpha::kOpaque);
    } else {
      SplatRasterTarget view_target;
      view_target.framebuffer = view_framebuffer_.id();
      view_target.image_size = {W, H};
      raster_.clear(view_target);
      raster_.draw(buffers_, view_target);
      raster_.composite_from(view_target_, tile, settings.background);
    }
    stamp(4 * size_t(view) + 3);
  }
  finish_stats(geometry.views, geometry.views);
}

void GlPerViewRenderer::render_compute(std::span<const render::Camera> cameras, const render::RasterSettings& settings,
                                       const TileViewsTarget& target) {
  begin_timing(1);
  stamp(0);
  tiles_->render_views(scene_, cameras, settings, target, [this](int k) { stamp(size_t(k)); });
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
