#include "render/rasterizer_cpu.hpp"

namespace lfd::render {

RasterImage rasterize(const GaussianScene& scene, const Camera& camera,
                      const RasterSettings& settings, std::span<const uint32_t> subset) {
  const auto projected = preprocess(scene, camera, settings, subset);
  const auto bins = bin_and_sort(projected, camera.width, camera.height);
  return blend(projected, bins, camera.width, camera.height, settings.background);
}

}  // namespace lfd::render
