// Stage 2 of the reference forward pass (rasterizer_impl.cu duplicateWithKeys + radix sort +
// identifyTileRanges): one entry per (Gaussian, touched tile), ordered by tile then by view-space
// depth. The reference sorts the 64-bit keys (tile << 32 | depth bits) with a stable radix sort
// over entries emitted in Gaussian order, so ties in depth keep the Gaussian order; a global
// stable order by (depth, index) scattered into tiles reproduces exactly that.
#include <algorithm>
#include <numeric>

#include <omp.h>

#include "render/tile_binning.hpp"

namespace lfd::render {

TileBins bin_and_sort(const std::vector<ProjectedGaussian>& projected, int width, int height) {
  TileBins bins;
  bins.tiles_x = (width + kTileSize - 1) / kTileSize;
  bins.tiles_y = (height + kTileSize - 1) / kTileSize;
  const size_t tiles = size_t(bins.tiles_x) * size_t(bins.tiles_y);

  std::vector<uint32_t> order;
  order.reserve(projected.size());
  for (uint32_t i = 0; i < projected.size(); ++i)
    if (projected[i].radius_px > 0) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const float da = projected[a].depth, db = projected[b].depth;
    return da < db || (da == db && a < b);
  });

  // Per-thread contiguous slices of the depth order; counts per (slice, tile) give each slice
  // its write offsets, so the scatter is parallel and keeps the depth order inside each tile.
  const int slices = std::max(1, std::min<int>(omp_in_parallel() ? 1 : omp_get_max_threads(),
                                               int(order.size() / 4096) + 1));
  std::vector<std::vector<uint32_t>> counts(size_t(slices), std::vector<uint32_t>(tiles, 0));
  const auto slice_begin = [&](int s) { return order.size() * size_t(s) / size_t(slices); };
#pragma omp parallel for num_threads(slices) if (slices > 1)
  for (int s = 0; s < slices; ++s) {
    auto& c = counts[size_t(s)];
    for (size_t k = slice_begin(s); k < slice_begin(s + 1); ++k) {
      const ProjectedGaussian& g = projected[order[k]];
      for (int ty = g.rect_min.y; ty < g.rect_max.y; ++ty)
        for (int tx = g.rect_min.x; tx < g.rect_max.x; ++tx) ++c[size_t(ty) * bins.tiles_x + tx];
    }
  }
  bins.range_begin.assign(tiles + 1, 0);
  uint32_t total = 0;
  for (size_t t = 0; t < tiles; ++t) {
    bins.range_begin[t] = total;
    for (int s = 0; s < slices; ++s) {
      const uint32_t c = counts[size_t(s)][t];
      counts[size_t(s)][t] = total;  // becomes the slice's write cursor for tile t
      total += c;
    }
  }
  bins.range_begin[tiles] = total;
  bins.ids.resize(total);
#pragma omp parallel for num_threads(slices) if (slices > 1)
  for (int s = 0; s < slices; ++s) {
    auto& cursor = counts[size_t(s)];
    for (size_t k = slice_begin(s); k < slice_begin(s + 1); ++k) {
      const ProjectedGaussian& g = projected[order[k]];
      for (int ty = g.rect_min.y; ty < g.rect_max.y; ++ty)
        for (int tx = g.rect_min.x; tx < g.rect_max.x; ++tx)
          bins.ids[cursor[size_t(ty) * bins.tiles_x + tx]++] = order[k];
    }
  }
  return bins;
}

}  // namespace lfd::render
