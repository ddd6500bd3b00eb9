#pragma once
// The CPU renderers (the references the GL ones are measured against): each wraps one call of
// render/ or voxel/ on all OpenMP threads; memory is the process's peak RSS. Made by
// lightfield/renderer_factory.hpp.
#include <memory>

#include "lightfield/light_field_renderer.hpp"

namespace lfd::lightfield {

// render::render_quilt_per_view / render::render_view.
std::unique_ptr<LightFieldRenderer> make_cpu_gaussian_views(const RendererOptions& options);
// render::render_quilt_g2lf.
std::unique_ptr<LightFieldRenderer> make_cpu_g2lf(const RendererOptions& options);
// voxel::render_voxel_quilt_per_view / voxel::render_voxel_view.
std::unique_ptr<LightFieldRenderer> make_cpu_voxel_views(const RendererOptions& options);
// voxel::render_quilt_v2lf.
std::unique_ptr<LightFieldRenderer> make_cpu_v2lf(const RendererOptions& options);

}  // namespace lfd::lightfield
