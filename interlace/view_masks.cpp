#include "interlace/view_masks.hpp"

#include <atomic>

namespace lfd::interlace {

double ViewMasks::fraction_in() const {
  size_t in = 0, all = 0;
  for (const auto& m : masks) {
    for (uint8_t b : m) in += b != 0;
    all += m.size();
  }
  return all ? double(in) / double(all) : 0.0;
}

ViewMasks view_masks(const Interlacer& interlacer) {
  const render::QuiltLayout& layout = interlacer.layout();
  ViewMasks out;
  out.width = layout.tile_width();
  out.height = layout.tile_height();
  out.masks.assign(size_t(layout.views), std::vector<uint8_t>(size_t(out.width) * out.height, 0));
  const int screen_w = interlacer.lens().calibration().screen_w, screen_h = interlacer.lens().calibration().screen_h;
  const int w = out.width, th = out.height;
  // Rows run in parallel and may mark one texel together: relaxed atomic stores of the same value.
  const auto mark = [&](int view, int x, int y_bottom_up) {
    std::atomic_ref<uint8_t>(out.masks[size_t(view)][size_t(th - 1 - y_bottom_up) * w + x])
        .store(1, std::memory_order_relaxed);
  };
#pragma omp parallel for schedule(dynamic, 16)
  for (int row = 0; row < screen_h; ++row)
    for (int x = 0; x < screen_w; ++x)
      for (int c = 0; c < 3; ++c) {
        const SubpixelSample s = interlacer.sample_for(x, row, c);
        if (!s.inside) continue;
        const Interlacer::TileTexels t = interlacer.tile_texels(s.tile_u, s.tile_v);
        const auto mark_footprint = [&](int view) {
          mark(view, t.x0, t.y0);
          mark(view, t.x1, t.y0);
          mark(view, t.x0, t.y1);
          mark(view, t.x1, t.y1);
        };
        mark_footprint(s.view_a);
        if (s.weight_b > 0) mark_footprint(s.view_b);
      }
  return out;
}

}  // namespace lfd::interlace
