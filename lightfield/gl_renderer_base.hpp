#pragma once
// What the four GL renderers share (lightfield/gl_gaussian_renderers.cpp,
// lightfield/gl_voxel_renderers.cpp): the device, its scene bound again whenever the device
// uploads another, its quilt, GPU memory.
#include <cstdint>
#include <memory>

#include "gpu/panel/gl_direct_panel.hpp"
#include "lightfield/gl_renderer.hpp"

namespace lfd::lightfield {

class GlRendererBase : public GlLightFieldRenderer {
 public:
  GlRendererBase(const RendererOptions& options, scene::SceneKind kind, std::shared_ptr<GlDevice> device);

  std::string name() const override { return "gl"; }
  std::string device() const override { return device_->info().summary(); }
  int default_runs() const override { return 10; }
  const RendererOptions& options() const override { return options_; }
  void set_options(const RendererOptions& options) override;
  void set_scene(const scene::Scene& scene) override;
  QuiltStats render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override;
  const ImageF& read_quilt() override { return device_->read_quilt(); }
  std::string memory_kind() const override { return GlDevice::memory_kind(); }
  void reset_peak_memory() override { GlDevice::reset_peak_memory(); }
  size_t peak_memory_bytes() const override { return GlDevice::peak_memory_bytes(); }
  GlDevice& gl_device() const override { return *device_; }
  // render_panel_into the renderer's own panel texture (the quilt's format), then glFinish.
  QuiltStats render_panel(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                          const PanelOptions& options) override;
  // Per view: InputError (no direct pass).
  QuiltStats render_panel_into(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                               const PanelOptions& options, gpu::Texture& panel) override;
  // The last direct panel (render_panel of a sweeping-plane renderer), read back.
  const ImageF& read_panel() override;

 protected:
  // Binds the device's scene unless bound to its current upload (std::logic_error: none).
  void ensure_bound();
  // Makes the gpu:: renderers on the device's scene of this kind (dropping the old ones first).
  virtual void bind() = 0;
  // Called by set_options after the options changed.
  virtual void options_changed(const RendererOptions& old) {}
  void forget_binding() { bound_generation_ = UINT64_MAX; }
  // The direct pass for `lens`'s display (made again for another lens or panel size).
  gpu::GlDirectPanel& direct_pass(const display::LensModel& lens);
  interlace::DirectPanelOptions direct_options(const PanelOptions& panel, const glm::vec3& background) const;

  std::shared_ptr<GlDevice> device_;  // first: the context outlives what derived classes hold
  RendererOptions options_;

 private:
  scene::SceneKind kind_;
  uint64_t bound_generation_ = UINT64_MAX;
  std::unique_ptr<gpu::GlDirectPanel> direct_;
  const display::LensModel* direct_lens_ = nullptr;
  gpu::Texture panel_;
  ImageF panel_image_;
  bool panel_read_ = false;
};

}  // namespace lfd::lightfield
