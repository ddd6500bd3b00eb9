#include "lightfield/renderer_factory.hpp"

#include <stdexcept>

#include "lightfield/cpu_renderers.hpp"
#include "lightfield/gl_renderers.hpp"

namespace lfd::lightfield {
namespace {

bool sweeping(const RendererOptions& options) { return options.method == Method::kSweepingPlanes; }

std::unique_ptr<LightFieldRenderer> make_cpu_renderer(const RendererOptions& options, scene::SceneKind kind) {
  if (kind == scene::SceneKind::kVoxels) return sweeping(options) ? make_cpu_v2lf(options) : make_cpu_voxel_views(options);
  return sweeping(options) ? make_cpu_g2lf(options) : make_cpu_gaussian_views(options);
}

}  // namespace

std::unique_ptr<GlLightFieldRenderer> make_gl_renderer(const RendererOptions& options, scene::SceneKind kind,
                                                       std::shared_ptr<GlDevice> device) {
  if (options.backend != Backend::kGl) throw std::logic_error("make_gl_renderer: the options ask for the CPU");
  options.check();
  if (!device) device = GlDevice::open_headless();
  if (kind == scene::SceneKind::kVoxels)
    return sweeping(options) ? make_gl_v2lf(options, device) : make_gl_voxel_views(options, device);
  return sweeping(options) ? make_gl_g2lf(options, device) : make_gl_gaussian_views(options, device);
}

std::unique_ptr<LightFieldRenderer> make_renderer(const RendererOptions& options, scene::SceneKind kind,
                                                  std::shared_ptr<GlDevice> device) {
  if (options.backend == Backend::kGl) return make_gl_renderer(options, kind, std::move(device));
  options.check();
  return make_cpu_renderer(options, kind);
}

std::shared_ptr<GlDevice> open_device(Backend backend) {
  return backend == Backend::kGl ? GlDevice::open_headless() : nullptr;
}

Backend backend_for(const std::shared_ptr<GlDevice>& device) { return device ? Backend::kGl : Backend::kCpu; }

}  // namespace lfd::lightfield
