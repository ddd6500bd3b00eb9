#include "lightfield/gl_renderer_base.hpp"

#include <stdexcept>

#include <epoxy/gl.h>

#include "lightfield/renderer_checks.hpp"

namespace lfd::lightfield {

GlRendererBase::GlRendererBase(const RendererOptions& options, SceneKind kind, std::shared_ptr<GlDevice> device)
    : device_(std::move(device)), options_(options), kind_(kind) {
  if (!device_) throw std::logic_error("a GL renderer needs a GL device");
}

void GlRendererBase::set_options(const RendererOptions& options) {
  check_same_renderer(options_, options);
  const RendererOptions old = options_;
  options_ = options;
  options_changed(old);
}

void GlRendererBase::set_scene(const LightFieldScene& scene) {
  check_scene_kind(kind_, scene);
  device_->upload(scene);
  ensure_bound();
}

void GlRendererBase::ensure_bound() {
  if (bound_generation_ == device_->scene_generation()) return;
  const bool uploaded = kind_ == SceneKind::kVoxels ? device_->voxels() != nullptr : device_->gaussians() != nullptr;
  if (!uploaded) throw std::logic_error("LightFieldRenderer: set_scene before rendering");
  bind();
  bound_generation_ = device_->scene_generation();
}

QuiltStats GlRendererBase::render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) {
  const QuiltStats stats = render_quilt_into(geometry, layout, device_->quilt(layout, options_.gl.quilt_format));
  glFinish();  // the frame is complete when the call returns: its wall time is the GPU frame
  return stats;
}

}  // namespace lfd::lightfield
