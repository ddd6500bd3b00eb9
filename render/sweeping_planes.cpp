// Alg. 1 lines 4-5: every chunk rasterised into its own plane from the reference camera with the
// reference rasterizer (background 0, so the colour is premultiplied and T is the chunk's
// transmittance). Chunks run in parallel; the rasterizer inside each runs on one thread.
#include <algorithm>
#include <cmath>

#include "render/rasterizer_cpu.hpp"
#include "render/sweeping_planes.hpp"
#include "util/huge_pages.hpp"
#include "util/progress.hpp"

namespace lfd::render {

size_t SweepingPlanes::bytes() const {
  return texels_u8.size() + texels_f32.size() * sizeof(float) +
         (row_first.size() + row_last.size()) * sizeof(int32_t);
}

SweepingPlanes render_sweeping_planes(const GaussianScene& scene, const QuiltGeometry& geometry,
                                      const ReferenceCamera& ref, const DepthChunks& chunks,
                                      PlanePrecision precision, const RasterSettings& settings) {
  SweepingPlanes planes;
  planes.count = int(chunks.members.size());
  planes.width = ref.camera.width;
  planes.height = ref.camera.height;
  planes.precision = precision;
  planes.plane_depth = chunks.plane_depth;
  const size_t texels = size_t(planes.width) * planes.height;
  // Every texel and row range is written below; the planes are the largest buffer of a frame
  // (64 planes of 512x512: 67 MB in u8, 268 MB in f32), so they go on huge pages.
  if (precision == PlanePrecision::kU8)
    assign_large(planes.texels_u8, texels * 4 * planes.count, uint8_t(0));
  else
    assign_large(planes.texels_f32, texels * 4 * planes.count, 0.0f);
  planes.row_first.assign(size_t(planes.count) * planes.height, planes.width);
  planes.row_last.assign(size_t(planes.count) * planes.height, -1);

  RasterSettings chunk_settings = settings;
  chunk_settings.background = glm::vec3(0.0f);
  chunk_settings.sh_origin = geometry.base.position_world;

  Progress progress("sweeping planes", planes.count);
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = 0; k < planes.count; ++k) {
    const RasterImage img = rasterize(scene, ref.camera, chunk_settings, chunks.members[size_t(k)]);
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
