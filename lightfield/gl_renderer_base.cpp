#include "lightfield/gl_renderer_base.hpp"

#include <stdexcept>

#include <epoxy/gl.h>

#include "gpu/panel/gl_interlacer.hpp"
#include "lightfield/renderer_checks.hpp"

namespace lfd::lightfield {

GlRendererBase::GlRendererBase(const RendererOptions& options, scene::SceneKind kind, std::shared_ptr<GlDevice> device)
    : device_(std::move(device)), options_(options), kind_(kind) {
  if (!device_) throw std::logic_error("a GL renderer needs a GL device");
}

void GlRendererBase::set_options(const RendererOptions& options) {
  check_same_renderer(options_, options);
  const RendererOptions old = options_;
  options_ = options;
  options_changed(old);
}

void GlRendererBase::set_scene(const scene::Scene& scene) {
  check_scene_kind(kind_, scene);
  device_->upload(scene);
  ensure_bound();
}

void GlRendererBase::ensure_bound() {
  if (bound_generation_ == device_->scene_generation()) return;
  const bool uploaded = kind_ == scene::SceneKind::kVoxels ? device_->voxels() != nullptr : device_->gaussians() != nullptr;
  if (!uploaded) throw std::logic_error("LightFieldRenderer: set_scene before rendering");
  bind();
  bound_generation_ = device_->scene_generation();
}

QuiltStats GlRendererBase::render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) {
  const QuiltStats stats = render_quilt_into(geometry, layout, device_->quilt(layout, options_.gl.quilt_format));
  glFinish();  // the frame is complete when the call returns: its wall time is the GPU frame
  return stats;
}

gpu::GlDirectPanel& GlRendererBase::direct_pass(const display::LensModel& lens) {
  // Another lens (even one at the same address) needs its own constants: compare the panel too.
  const bool hardware_bilinear = options_.gl.direct_hardware_bilinear;
  const gpu::DirectPanelPass stage = !options_.gl.direct_compute   ? gpu::DirectPanelPass::kFragment
                                     : options_.gl.direct_plane_major ? gpu::DirectPanelPass::kComputePlaneMajor
                                                                      : gpu::DirectPanelPass::kCompute;
  if (!direct_ || direct_lens_ != &lens || direct_->panel_width() != lens.calibration().screen_w ||
      direct_->panel_height() != lens.calibration().screen_h || direct_->hardware_bilinear() != hardware_bilinear ||
      direct_->pass() != stage) {
    direct_ = std::make_unique<gpu::GlDirectPanel>(lens, hardware_bilinear, stage);
    direct_lens_ = &lens;
  }
  return *direct_;
}

interlace::DirectPanelOptions GlRendererBase::direct_options(const PanelOptions& panel,
                                                             const glm::vec3& background) const {
  interlace::DirectPanelOptions o;
  o.filter = options_.direct_filter;
  o.background = background;
  o.overscan = panel.overscan;
  o.invert_views = panel.invert_views;
  return o;
}

QuiltStats GlRendererBase::render_panel(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                                        const PanelOptions& options) {
  const GLenum format = options_.gl.quilt_format;
  const int w = lens.calibration().screen_w, h = lens.calibration().screen_h;
  if (!panel_.id() || panel_.width() != w || panel_.height() != h || panel_.internal_format() != format)
    panel_ = gpu::Texture(format, w, h);
  const QuiltStats stats = render_panel_into(geometry, lens, options, panel_);
  glFinish();  // the frame is complete when the call returns, as render_quilt's
  panel_read_ = false;
  return stats;
}

QuiltStats GlRendererBase::render_panel_into(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                                             const PanelOptions& options, gpu::Texture&) {
  return LightFieldRenderer::render_panel(geometry, lens, options);  // the one-line error
}

const ImageF& GlRendererBase::read_panel() {
  if (!panel_.id()) return LightFieldRenderer::read_panel();  // no direct frame yet: the one-line error
  if (!panel_read_) {
    panel_image_ = gpu::image_from_texture(panel_);
    panel_read_ = true;
  }
  return panel_image_;
}

}  // namespace lfd::lightfield
