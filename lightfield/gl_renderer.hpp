#pragma once
// The GL renderers' one extension of LightFieldRenderer: a quilt rendered into the caller's
// texture on the device's context, without waiting for the GPU (the viewer interlaces it on the
// GPU; no read-back, no glFinish). render_quilt is this into the device's quilt, then glFinish.
#include <memory>

#include "gpu/gl/gl_objects.hpp"
#include "lightfield/gl_device.hpp"
#include "lightfield/light_field_renderer.hpp"

namespace lfd::lightfield {

class GlLightFieldRenderer : public LightFieldRenderer {
 public:
  // `quilt`: layout.width x layout.height, GL_RGBA8, GL_RGBA16F or GL_RGBA32F; rows bottom-up,
  // view 0 in the bottom-left tile; 0 outside the tiles.
  virtual QuiltStats render_quilt_into(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                       gpu::Texture& quilt) = 0;
  // The direct panel (LightFieldRenderer::render_panel) into the caller's `panel` (screenW x
  // screenH, colour-renderable, rows bottom-up), without waiting for the GPU. Sweeping-plane
  // renderers only (InputError otherwise).
  virtual QuiltStats render_panel_into(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                                       const PanelOptions& options, gpu::Texture& panel) = 0;
  virtual GlDevice& gl_device() const = 0;
};

}  // namespace lfd::lightfield
