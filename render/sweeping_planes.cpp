// Alg. 1 lines 4-5: every chunk rasterised into its own plane from the reference camera with the
// reference rasterizer (background 0, so the colour is premultiplied and T is the chunk's
// transmittance). Chunks run in parallel, largest first, the rasterizer inside each on one
// thread; with fewer chunks than threads, one after another on all threads.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "render/rasterizer_cpu.hpp"
#include "render/sweeping_planes.hpp"
#include "util/huge_pages.hpp"
#include "util/progress.hpp"

namespace lfd::render {

size_t SweepingPlanes::bytes() const {
  return texels_u8.size() + texels_f32.size() * sizeof(float) +
         (row_first.size() + row_last.size()) * sizeof(int32_t);
}

namespace {

// The chunks in decreasing order of their estimated rasterisation cost, so that they can be
// handed out largest first (LPT scheduling): a far chunk of few but huge Gaussians (a sky dome)
// can cost several near ones, and started last it runs alone on one core while the others
// idle (14 % of the planes' time in one chunk on a 150k tabletop). Estimate: per member one
// unit plus the pixels of its 3-sigma square, at most the image.
std::vector<int> largest_first(const scene::GaussianScene& scene, const Camera& camera, const DepthChunks& chunks) {
  const int count = int(chunks.members.size());
  const double image_px = double(camera.width) * camera.height;
  const double focal_px = std::max(camera.focal_x_px(), camera.focal_y_px());
  std::vector<double> cost(static_cast<size_t>(count), 0.0);
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < count; ++k) {
    double c = 0.0;
    for (uint32_t i : chunks.members[size_t(k)]) {
      const auto& p = scene.positions[i];
      const auto& s = scene.scales[i];
      const float z = std::max(camera.to_camera(glm::vec3(p[0], p[1], p[2])).z, 1e-3f);
      const double radius_px = 3.0 * std::max({s[0], s[1], s[2]}) * focal_px / z;
      c += 1.0 + std::min(image_px, 4.0 * radius_px * radius_px);
    }
    cost[size_t(k)] = c;
  }
  std::vector<int> order(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) order[size_t(k)] = k;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[size_t(a)] > cost[size_t(b)]; });
  return order;
}

}  // namespace

SweepingPlanes render_sweeping_planes(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                                      const ReferenceCamera& ref, const DepthChunks& chunks,
                                      PlanePrecision precision, const RasterSettings& settings) {
  RasterSettings chunk_settings = settings;
  chunk_settings.background = glm::vec3(0.0f);
  chunk_settings.sh_origin = geometry.base.position_world;
  return make_sweeping_planes(
      ref, chunks.plane_depth, precision,
      [&](int k) { return rasterize(scene, ref.camera, chunk_settings, chunks.members[size_t(k)]); },
      largest_first(scene, ref.camera, chunks));
}

SweepingPlanes make_sweeping_planes(const ReferenceCamera& ref, const std::vector<float>& plane_depth,
                                    PlanePrecision precision, const std::function<RasterImage(int)>& render_chunk,
                                    const std::vector<int>& order) {
  SweepingPlanes planes;
  planes.count = int(plane_depth.size());
  planes.width = ref.camera.width;
  planes.height = ref.camera.height;
  planes.precision = precision;
  planes.plane_depth = plane_depth;
  const size_t texels = size_t(planes.width) * planes.height;
  // Every texel and row range is written below; the planes are the largest buffer of a frame
  // (64 planes of 512x512: 67 MB in u8, 268 MB in f32), so they go on huge pages.
  if (precision == PlanePrecision::kU8)
    assign_large(planes.texels_u8, texels * 4 * planes.count, uint8_t(0));
  else
    assign_large(planes.texels_f32, texels * 4 * planes.count, 0.0f);
  planes.row_first.assign(size_t(planes.count) * planes.height, planes.width);
  planes.row_last.assign(size_t(planes.count) * planes.height, -1);

  Progress progress("sweeping planes", planes.count);
  // Fewer chunks than threads: one chunk at a time, each rasterised on all threads (the
  // rasterizer's stages are parallel and deterministic), instead of idle threads.
  const bool chunks_in_parallel = planes.count >= omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) if (chunks_in_parallel)
  for (int n = 0; n < planes.count; ++n) {
    const int k = order.empty() ? n : order[size_t(n)];
    const RasterImage img = render_chunk(k);
    for (int y = 0; y < planes.height; ++y) {
      int first = planes.width, last = -1;
      for (int x = 0; x < planes.width; ++x) {
        const size_t p = size_t(y) * planes.width + x;
        const size_t o = (size_t(k) * texels + p) * 4;
        const float r = img.rgb[3 * p], g = img.rgb[3 * p + 1], b = img.rgb[3 * p + 2];
        const float t = img.transmittance[p];
        bool empty;
        if (precision == PlanePrecision::kU8) {
          const auto q = [](float v) { return uint8_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); };
          uint8_t* texel = &planes.texels_u8[o];
          texel[0] = q(r); texel[1] = q(g); texel[2] = q(b); texel[3] = q(t);
          empty = texel[0] == 0 && texel[1] == 0 && texel[2] == 0 && texel[3] == 255;
        } else {
          float* texel = &planes.texels_f32[o];
          texel[0] = r; texel[1] = g; texel[2] = b; texel[3] = t;
          empty = r == 0.0f && g == 0.0f && b == 0.0f && t == 1.0f;
        }
        if (!empty) {
          first = std::min(first, x);
          last = x;
        }
      }
      planes.row_first[size_t(k) * planes.height + y] = first;
      planes.row_last[size_t(k) * planes.height + y] = last;
    }
    progress.advance();
  }
  progress.finish();
  return planes;
}

}  // namespace lfd::render
