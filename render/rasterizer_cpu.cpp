#include "render/rasterizer_cpu.hpp"

namespace lfd::render {

RasterImage rasterize(const scene::GaussianScene& scene, const Camera& camera,
                      const RasterSettings& settings, std::span<const uint32_t> subset) {
  const auto projected = preprocess(scene, camera, settings, subset);
  const auto bins = bin_and_sort(projected, camera.width, camera.height);
  return blend(projected, bins, camera.width, camera.height, settings.background);
}

RasterImage rasterize_masked(const scene::GaussianScene& scene, const Camera& camera, std::span<const uint8_t> pixel_mask,
                             const RasterSettings& settings) {
  const auto projected = preprocess(scene, camera, settings);
  const auto bins = bin_and_sort(projected, camera.width, camera.height);
  return blend(projected, bins, camera.width, camera.height, settings.background, pixel_mask);
}

}  // namespace lfd::render
