// The GL renderers of Gaussian scenes: every view alone (gpu::GlPerViewRenderer) and G2LF
// (gpu::GlG2lfRenderer), on the device's uploaded scene.
#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/probes/gl_raster_probe.hpp"
#include "lightfield/gl_renderer_base.hpp"
#include "lightfield/gl_renderers.hpp"
#include "lightfield/renderer_checks.hpp"

namespace lfd::lightfield {
namespace {

class GlGaussianViews final : public GlRendererBase {
 public:
  GlGaussianViews(const RendererOptions& options, std::shared_ptr<GlDevice> device)
      : GlRendererBase(options, scene::SceneKind::kGaussians, std::move(device)) {}

  QuiltStats render_quilt_into(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                               gpu::Texture& quilt) override {
    ensure_bound();
    views_->render_quilt(geometry, layout, options_.raster_settings(), quilt);
    const gpu::GlPerViewStats& s = views_->stats();
    return {.seconds_raster = s.preprocess_s + s.sort_s + s.raster_s};
  }
  ImageF render_view(const render::QuiltGeometry& geometry, int view) override {
    ensure_bound();
    return rgb_image(views_->render_view_image(geometry.view_camera(view), options_.raster_settings()));
  }

 private:
  void bind() override {
    views_.reset();  // it holds the old scene by reference
    scene_ = device_->gaussians();
    gpu::GlPerViewOptions o;
    o.gpu_timers = options_.gl.gpu_timers;
    o.timer_reads = options_.gl.timer_reads;
    o.depth_key_bits = options_.gl.depth_key_bits;
    o.normalised_depth_keys = options_.gl.normalised_depth_keys;
    o.accumulation_format = options_.gl.per_view_accumulation_format;
    o.raster = gpu::resolve_raster_path(options_.gl.raster);
    views_ = std::make_unique<gpu::GlPerViewRenderer>(*scene_, o);
  }
  void options_changed(const RendererOptions& old) override {
    if (old.gl.gpu_timers != options_.gl.gpu_timers || old.gl.timer_reads != options_.gl.timer_reads ||
        old.gl.depth_key_bits != options_.gl.depth_key_bits ||
        old.gl.normalised_depth_keys != options_.gl.normalised_depth_keys ||
        old.gl.per_view_accumulation_format != options_.gl.per_view_accumulation_format ||
        old.gl.raster != options_.gl.raster)
      forget_binding();  // the timers, the sort's key bits, the blending target and the path are made with it
  }

  std::shared_ptr<const gpu::GlScene> scene_;
  std::unique_ptr<gpu::GlPerViewRenderer> views_;
};

class GlG2lf final : public GlRendererBase {
 public:
  GlG2lf(const RendererOptions& options, std::shared_ptr<GlDevice> device)
      : GlRendererBase(options, scene::SceneKind::kGaussians, std::move(device)) {}

  QuiltStats render_quilt_into(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                               gpu::Texture& quilt) override {
    ensure_bound();
    g2lf_->render_quilt(geometry, layout, options_.gl_g2lf(), options_.raster_settings(), quilt);
    const gpu::GlG2lfStats& s = g2lf_->stats();
    return {.planes = options_.planes.chunks, .plane_bytes = s.plane_bytes, .binned = s.gaussians_in_frustum,
            .seconds_binning = s.seconds_binning, .seconds_planes = s.seconds_planes,
            .seconds_swizzle = s.seconds_swizzle};
  }
  QuiltStats render_panel_into(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                               const PanelOptions& panel, gpu::Texture& target) override {
    ensure_bound();
    gpu::GlDirectPanel& pass = direct_pass(lens);
    const render::RasterSettings settings = options_.raster_settings();
    g2lf_->render_panel(geometry, options_.gl_g2lf(), settings, pass, direct_options(panel, settings.background),
                        target);
    const gpu::GlG2lfStats& s = g2lf_->stats();
    return {.planes = options_.planes.chunks, .plane_bytes = s.plane_bytes, .binned = s.gaussians_in_frustum,
            .seconds_binning = s.seconds_binning, .seconds_planes = s.seconds_planes,
            .seconds_swizzle = s.seconds_swizzle};
  }
  // G2LF renders whole quilts: one view is the per-view renderer's.
  ImageF render_view(const render::QuiltGeometry& geometry, int view) override {
    ensure_bound();
    gpu::GlPerViewOptions o;
    o.raster = gpu::resolve_raster_path(options_.gl.raster);
    gpu::GlPerViewRenderer views(*scene_, o);
    return rgb_image(views.render_view_image(geometry.view_camera(view), options_.raster_settings()));
  }

 private:
  void bind() override {
    g2lf_.reset();  // it holds the old scene by reference
    scene_ = device_->gaussians();
    g2lf_ = std::make_unique<gpu::GlG2lfRenderer>(*scene_, device_->info());
  }

  std::shared_ptr<const gpu::GlScene> scene_;
  std::unique_ptr<gpu::GlG2lfRenderer> g2lf_;
};

}  // namespace

std::unique_ptr<GlLightFieldRenderer> make_gl_gaussian_views(const RendererOptions& options,
                                                             std::shared_ptr<GlDevice> device) {
  return std::make_unique<GlGaussianViews>(options, std::move(device));
}

std::unique_ptr<GlLightFieldRenderer> make_gl_g2lf(const RendererOptions& options, std::shared_ptr<GlDevice> device) {
  return std::make_unique<GlG2lf>(options, std::move(device));
}

}  // namespace lfd::lightfield
