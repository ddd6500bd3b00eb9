// The GL renderers of voxel scenes: every view alone (gpu::GlVoxelViews, drawn by the raster
// pipeline or the compute tile rasterizer: options.gl.raster) and V2LF (gpu::GlV2lfRenderer), on
// the device's uploaded scene.
#include "gpu/probes/gl_raster_probe.hpp"
#include "gpu/voxels/gl_v2lf.hpp"
#include "gpu/voxels/gl_voxel_views.hpp"
#include "lightfield/gl_renderer_base.hpp"
#include "lightfield/gl_renderers.hpp"
#include "lightfield/renderer_checks.hpp"
#include "util/error.hpp"

namespace lfd::lightfield {
namespace {

// One view of `scene` alone through its off-axis camera (as gpu::render_voxel_view_gl).
ImageF render_voxel_view(gpu::GlVoxelViews& views, const render::QuiltGeometry& geometry, int view,
                         const voxel::VoxelRenderSettings& settings) {
  if (view < 0 || view >= geometry.views) throw_input_error("view {} is outside 0..{}", view, geometry.views - 1);
  return rgb_image(views.render_view(geometry.view_camera(view), settings));
}

class GlVoxelViewsRenderer final : public GlRendererBase {
 public:
  GlVoxelViewsRenderer(const RendererOptions& options, std::shared_ptr<GlDevice> device)
      : GlRendererBase(options, scene::SceneKind::kVoxels, std::move(device)) {}

  QuiltStats render_quilt_into(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                               gpu::Texture& quilt) override {
    ensure_bound();
    views_->render_quilt(geometry, layout, options_.voxel_settings(), quilt);
    return {};
  }
  ImageF render_view(const render::QuiltGeometry& geometry, int view) override {
    ensure_bound();
    return render_voxel_view(*views_, geometry, view, options_.voxel_settings());
  }

 private:
  void bind() override {
    views_.reset();  // it holds the old scene by reference
    scene_ = device_->voxels();
    views_ = std::make_unique<gpu::GlVoxelViews>(
        *scene_, gpu::resolve_raster_path(options_.gl.raster, gpu::RasterSubject::kVoxels));
  }
  void options_changed(const RendererOptions& old) override {
    if (old.gl.raster != options_.gl.raster) forget_binding();  // the path is made with the views
  }

  std::shared_ptr<const gpu::GlVoxelScene> scene_;
  std::unique_ptr<gpu::GlVoxelViews> views_;
};

// The stage times are those of the newest timed frame (gpu_timers; the viewer reads them late).
QuiltStats v2lf_quilt_stats(const gpu::GlV2lfStats& s) {
  return {.planes = s.planes, .plane_bytes = s.plane_bytes, .binned = s.voxels_binned,
          .voxels_split = s.voxels_split, .seconds_binning = s.seconds_binning,
          .seconds_planes = s.seconds_planes, .seconds_swizzle = s.seconds_swizzle};
}

class GlV2lf final : public GlRendererBase {
 public:
  GlV2lf(const RendererOptions& options, std::shared_ptr<GlDevice> device)
      : GlRendererBase(options, scene::SceneKind::kVoxels, std::move(device)) {}

  QuiltStats render_quilt_into(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                               gpu::Texture& quilt) override {
    ensure_bound();
    const glm::vec3 background = options_.background.value_or(scene_->scene().background);
    v2lf_->render_quilt(geometry, layout, options_.gl_v2lf(), background, quilt);
    const gpu::GlV2lfStats& s = v2lf_->stats();
    return v2lf_quilt_stats(v2lf_->stats());
  }
  QuiltStats render_panel_into(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                               const PanelOptions& panel, gpu::Texture& target) override {
    ensure_bound();
    gpu::GlDirectPanel& pass = direct_pass(lens);
    const glm::vec3 background = options_.background.value_or(scene_->scene().background);
    v2lf_->render_panel(geometry, options_.gl_v2lf(), pass, direct_options(panel, background), target);
    const gpu::GlV2lfStats& s = v2lf_->stats();
    return v2lf_quilt_stats(v2lf_->stats());
  }
  // V2LF renders whole quilts: one view is the per-view renderer's.
  ImageF render_view(const render::QuiltGeometry& geometry, int view) override {
    ensure_bound();
    gpu::GlVoxelViews views(*scene_, gpu::resolve_raster_path(options_.gl.raster, gpu::RasterSubject::kVoxels));
    return render_voxel_view(views, geometry, view, options_.voxel_settings());
  }

 private:
  void bind() override {
    v2lf_.reset();  // it holds the old scene by reference
    scene_ = device_->voxels();
    v2lf_ = std::make_unique<gpu::GlV2lfRenderer>(*scene_, device_->info());
  }

  std::shared_ptr<const gpu::GlVoxelScene> scene_;
  std::unique_ptr<gpu::GlV2lfRenderer> v2lf_;
};

}  // namespace

std::unique_ptr<GlLightFieldRenderer> make_gl_voxel_views(const RendererOptions& options,
                                                          std::shared_ptr<GlDevice> device) {
  return std::make_unique<GlVoxelViewsRenderer>(options, std::move(device));
}

std::unique_ptr<GlLightFieldRenderer> make_gl_v2lf(const RendererOptions& options, std::shared_ptr<GlDevice> device) {
  return std::make_unique<GlV2lf>(options, std::move(device));
}

}  // namespace lfd::lightfield
