#include "voxel/plane_lowpass.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lfd::voxel {

float view_antialias_variance(const scene::VoxelScene& scene) {
  return scene.supersampling > 1.0f ? 1.0f / 6.0f : 0.0f;
}

float plane_lowpass_variance(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                             const render::ReferenceCamera& ref, int plane_scale) {
  return render::adaptive_filter_variance(geometry, ref, plane_scale, view_antialias_variance(scene));
}

namespace {

// One axis of the separable filter over `channels` interleaved channels: `count` samples from
// `first` along the axis (`stride` apart) on `lines` lines from `line_first` (`line_stride`
// apart), edges clamped to the range.
void blur_axis(std::vector<float>& data, int channels, int first, int count, int stride, int line_first, int lines,
               int line_stride, const std::vector<float>& kernel) {
  const int radius = int(kernel.size() / 2);
  std::vector<float> line(size_t(count) * channels);
  for (int l = 0; l < lines; ++l) {
    float* base = data.data() + size_t(line_first + l) * line_stride + size_t(first) * stride;
    for (int i = 0; i < count; ++i)
      for (int c = 0; c < channels; ++c) line[size_t(i) * channels + c] = base[size_t(i) * stride + c];
    for (int i = 0; i < count; ++i)
      for (int c = 0; c < channels; ++c) {
        float sum = 0.0f;
        for (int k = -radius; k <= radius; ++k)
          sum += kernel[size_t(k + radius)] * line[size_t(std::clamp(i + k, 0, count - 1)) * channels + c];
        base[size_t(i) * stride + c] = sum;
      }
  }
}

}  // namespace

std::vector<float> gaussian_lowpass_kernel(float variance_px2) {
  if (!(variance_px2 >= 0.01f)) return {};
  const float sigma = std::sqrt(variance_px2);
  const int radius = std::max(1, int(std::ceil(3.0f * sigma)));
  std::vector<float> kernel(size_t(2 * radius + 1));
  float sum = 0.0f;
  for (int k = -radius; k <= radius; ++k) sum += kernel[size_t(k + radius)] = std::exp(-0.5f * k * k / variance_px2);
  for (float& w : kernel) w /= sum;
  return kernel;
}

void gaussian_lowpass(render::RasterImage& image, float variance_px2) {
  const std::vector<float> kernel = gaussian_lowpass_kernel(variance_px2);
  if (kernel.empty()) return;
  const int radius = int(kernel.size() / 2);
  // Only the box around the non-empty texels (C = 0, T = 1 is empty), grown by the radius: a
  // chunk covers a small part of most planes. Beyond it every texel within reach is empty, so
  // clamping at the box's edge reads what the whole plane would give.
  const int w = image.width, h = image.height;
  int x0 = w, x1 = -1, y0 = h, y1 = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t p = size_t(y) * w + x;
      if (image.transmittance[p] == 1.0f && image.rgb[3 * p] == 0.0f && image.rgb[3 * p + 1] == 0.0f &&
          image.rgb[3 * p + 2] == 0.0f)
        continue;
      x0 = std::min(x0, x);
      x1 = std::max(x1, x);
      y0 = std::min(y0, y);
      y1 = std::max(y1, y);
    }
  if (x1 < x0) return;
  x0 = std::max(0, x0 - radius);
  y0 = std::max(0, y0 - radius);
  x1 = std::min(w - 1, x1 + radius);
  y1 = std::min(h - 1, y1 + radius);
  const int bw = x1 - x0 + 1, bh = y1 - y0 + 1;
  blur_axis(image.rgb, 3, x0, bw, 3, y0, bh, 3 * w, kernel);
  blur_axis(image.rgb, 3, y0, bh, 3 * w, x0, bw, 3, kernel);
  blur_axis(image.transmittance, 1, x0, bw, 1, y0, bh, w, kernel);
  blur_axis(image.transmittance, 1, y0, bh, w, x0, bw, 1, kernel);
}

}  // namespace lfd::voxel
