#pragma once
// Sweeping planes of flat-coloured layers built by hand (no rasterizer): layer k is a vertical
// band of one colour and transmittance 0.35 at its own depth, the bands overlapping so that
// edges of every layer cross the view. The direct-panel tests (CPU and GL) composite them.
#include <vector>

#include <glm/glm.hpp>

#include "render/camera.hpp"
#include "render/quilt_geometry.hpp"
#include "render/sweeping_planes.hpp"

namespace lfd::test_planes {

struct FlatLayerScene {
  render::QuiltGeometry geometry;
  render::ReferenceCamera ref;
  render::SweepingPlanes planes;
  glm::vec3 background{0.1f, 0.2f, 0.3f};
};

inline FlatLayerScene flat_layer_scene(int width, int height, int views,
                                       render::PlanePrecision precision = render::PlanePrecision::kF32) {
  FlatLayerScene s;
  const render::Camera base = render::make_look_at_camera(glm::vec3(0, 0, 0), glm::vec3(0, 0, 2), glm::vec3(0, -1, 0),
                                                          0.8f, width, height);
  s.geometry = render::make_quilt_geometry(base, 2.0f, 40.0f, views);
  s.ref = render::make_reference_camera(s.geometry, render::forward_distance(s.geometry), 1);
  const std::vector<float> depths{1.2f, 1.7f, 2.0f, 2.6f, 3.5f};
  const glm::vec3 colours[5] = {{0.9f, 0.1f, 0.1f}, {0.1f, 0.8f, 0.2f}, {0.2f, 0.3f, 0.9f}, {0.9f, 0.9f, 0.1f},
                                {0.6f, 0.2f, 0.7f}};
  const int w = s.ref.camera.width, h = s.ref.camera.height;
  s.planes = render::make_sweeping_planes(s.ref, depths, precision, [&](int k) {
    render::RasterImage image;
    image.width = w;
    image.height = h;
    image.rgb.assign(size_t(w) * h * 3, 0.0f);
    image.transmittance.assign(size_t(w) * h, 1.0f);
    // Band k: columns [w (0.1 + 0.15 k), w (0.45 + 0.12 k)), rows [h 0.1 k, h (1 - 0.05 k)).
    const int x0 = int(w * (0.1 + 0.15 * k)), x1 = int(w * (0.45 + 0.12 * k));
    const int y0 = int(h * 0.1 * k), y1 = int(h * (1.0 - 0.05 * k));
    const float t = 0.35f;
    for (int y = y0; y < y1 && y < h; ++y)
      for (int x = x0; x < x1 && x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        image.transmittance[i] = t;
        for (int c = 0; c < 3; ++c) image.rgb[i * 3 + size_t(c)] = (1.0f - t) * colours[k][c];
      }
    return image;
  });
  return s;
}

}  // namespace lfd::test_planes
