#pragma once
// What every renderer checks of the calls made to it (std::logic_error: a caller's mistake).
#include "scene/scene.hpp"
#include "lightfield/renderer_options.hpp"
#include "render/blend.hpp"
#include "util/image.hpp"

namespace lfd::lightfield {

// set_options may change everything but the backend and the method.
void check_same_renderer(const RendererOptions& mine, const RendererOptions& asked);
// set_scene takes a scene of the renderer's kind.
void check_scene_kind(scene::SceneKind mine, const scene::Scene& scene);
// A raster image's RGB as an image (what render_view returns).
ImageF rgb_image(const render::RasterImage& image);

}  // namespace lfd::lightfield
