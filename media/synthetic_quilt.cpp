#include "media/synthetic_quilt.hpp"

#include <algorithm>
#include <cmath>

namespace lfd::media {

Image8 synthetic_quilt(const render::QuiltLayout& layout, int frame) {
  Image8 image(layout.width, layout.height, 3);
  const int tw = layout.tile_width(), th = layout.tile_height();
#pragma omp parallel for
  for (int y = 0; y < layout.height; ++y) {
    for (int x = 0; x < layout.width; ++x) {
      const int col = std::min(x / std::max(tw, 1), layout.cols - 1);
      const int row_from_top = std::min(y / std::max(th, 1), layout.rows - 1);
      const int view = (layout.rows - 1 - row_from_top) * layout.cols + col;
      const double u = (x - col * tw + 0.5) / tw, v = (y - row_from_top * th + 0.5) / th;
      const double hue = double(view) / std::max(layout.views, 1);
      // Disc moving right with the view and down with the frame.
      const double cx = 0.2 + 0.6 * hue, cy = 0.3 + 0.4 * (0.5 + 0.5 * std::sin(frame * 0.35));
      const double r = std::hypot((u - cx) * tw, (v - cy) * th) / (0.18 * th);
      const double disc = std::clamp(1.5 - r, 0.0, 1.0);
      // The view's number as vertical bars in the top band.
      const bool bar = v < 0.15 && u < 0.9 && int(u * 20) % 2 == 0 && int(u * 10) < (view % 9) + 1;
      const double base[3] = {0.25 + 0.5 * u, 0.2 + 0.6 * hue, 0.75 - 0.5 * v};
      for (int c = 0; c < 3; ++c) {
        double value = base[c] * (1 - disc) + (c == frame % 3 ? 0.95 : 0.1) * disc;
        if (bar) value = 1.0 - value;
        image.at(x, y, c) = uint8_t(std::lround(std::clamp(value, 0.0, 1.0) * 255));
      }
    }
  }
  return image;
}

void write_synthetic_quilt_video(const std::filesystem::path& path, const render::QuiltLayout& layout, int frames,
                                 EncoderOptions options) {
  options.width = layout.width;
  options.height = layout.height;
  VideoEncoder encoder(path, options);
  for (int f = 0; f < frames; ++f) encoder.add_frame(synthetic_quilt(layout, f));
  encoder.finish();
}

}  // namespace lfd::media
