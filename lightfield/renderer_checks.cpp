#include "lightfield/renderer_checks.hpp"

#include <stdexcept>

namespace lfd::lightfield {

void check_same_renderer(const RendererOptions& mine, const RendererOptions& asked) {
  if (asked.backend != mine.backend || asked.method != mine.method)
    throw std::logic_error("LightFieldRenderer::set_options: the backend and the method are the renderer's own");
}

void check_scene_kind(scene::SceneKind mine, const scene::Scene& scene) {
  if (scene.kind() != mine)
    throw std::logic_error(std::string("LightFieldRenderer::set_scene: this renderer does not render ") +
                           scene.primitives());
}

ImageF rgb_image(const render::RasterImage& image) {
  ImageF f(image.width, image.height, 3);
  f.pixels = image.rgb;
  return f;
}

}  // namespace lfd::lightfield
