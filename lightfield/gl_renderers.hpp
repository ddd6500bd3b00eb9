#pragma once
// The GL renderers: each wraps one renderer of gpu/ on a GlDevice (its context, its shared
// scene upload, its quilt); the same images as the CPU's to within the tolerances of tests/gpu.
// Made by lightfield/renderer_factory.hpp.
#include <memory>

#include "lightfield/gl_device.hpp"
#include "lightfield/gl_renderer.hpp"

namespace lfd::lightfield {

// gpu::GlPerViewRenderer (made again when gl.gpu_timers changes).
std::unique_ptr<GlLightFieldRenderer> make_gl_gaussian_views(const RendererOptions& options,
                                                             std::shared_ptr<GlDevice> device);
// gpu::GlG2lfRenderer.
std::unique_ptr<GlLightFieldRenderer> make_gl_g2lf(const RendererOptions& options, std::shared_ptr<GlDevice> device);
// gpu::GlVoxelViews.
std::unique_ptr<GlLightFieldRenderer> make_gl_voxel_views(const RendererOptions& options,
                                                          std::shared_ptr<GlDevice> device);
// gpu::GlV2lfRenderer.
std::unique_ptr<GlLightFieldRenderer> make_gl_v2lf(const RendererOptions& options, std::shared_ptr<GlDevice> device);

}  // namespace lfd::lightfield
