#pragma once
// The one place that chooses a light-field renderer: backend (CPU, GL) x scene kind (Gaussians,
// voxels) x method (every view alone, sweeping planes: G2LF, V2LF).
#include <memory>

#include "lightfield/gl_device.hpp"
#include "lightfield/gl_renderer.hpp"
#include "lightfield/light_field_renderer.hpp"

namespace lfd::lightfield {

// The renderer `options` ask for, for scenes of `kind`; checks the options first (InputError).
// A GL renderer renders on `device`, or on a headless device of its own when it is null
// (gpu::GlUnavailable without one); the CPU ones need none. Renderers made on one device share
// its scene upload and quilt.
std::unique_ptr<LightFieldRenderer> make_renderer(const RendererOptions& options, scene::SceneKind kind,
                                                  std::shared_ptr<GlDevice> device = nullptr);
// The same for options.backend == kGl, with the GL extension (std::logic_error for the CPU).
std::unique_ptr<GlLightFieldRenderer> make_gl_renderer(const RendererOptions& options, scene::SceneKind kind,
                                                       std::shared_ptr<GlDevice> device);

// The device renderers of `backend` share: a headless one for GL (gpu::GlUnavailable without
// one), none for the CPU.
std::shared_ptr<GlDevice> open_device(Backend backend);
// The backend a device stands for: GL with one, the CPU without (`--backend auto` without a
// context: GlDevice::adopt(nullptr) is null).
Backend backend_for(const std::shared_ptr<GlDevice>& device);

}  // namespace lfd::lightfield
