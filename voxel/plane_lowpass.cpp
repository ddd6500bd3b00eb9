#include "voxel/plane_lowpass.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lfd::voxel {

float view_antialias_variance(const VoxelScene& scene) {
  return scene.supersampling > 1.0f ? 1.0f / 6.0f : 0.0f;
}

float plane_lowpass_variance(const VoxelScene& scene, const render::QuiltGeometry& geometry,
                             const render::ReferenceCamera& ref, int plane_scale) {
  return render::adaptive_filter_variance(geometry, ref, plane_scale, view_antialias_variance(scene));
}

namespace {

// One axis of the separable filter over `channels` interleaved channels; `stride` is the
// distance between neighbours along the axis, `count` their number, `lines` and `line_stride`
// the lines across it.
void blur_axis(std::vector<float>& data, int channels, int count, int stride, int lines, int line_stride,
               const std::vector<float>& kernel) {
  const int radius = int(kernel.size() / 2);
  std::vector<float> line(size_t(count) * channels);
  for (int l = 0; l < lines; ++l) {
    float* base = data.data() + size_t(l) * line_stride;
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

void gaussian_lowpass(render::RasterImage& image, float variance_px2) {
  if (!(variance_px2 >= 0.01f)) return;
  const float sigma = std::sqrt(variance_px2);
  const int radius = std::max(1, int(std::ceil(3.0f * sigma)));
  std::vector<float> kernel(size_t(2 * radius + 1));
  float sum = 0.0f;
  for (int k = -radius; k <= radius; ++k) sum += kernel[size_t(k + radius)] = std::exp(-0.5f * k * k / variance_px2);
  for (float& w : kernel) w /= sum;
  const int w = image.width, h = image.height;
  blur_axis(image.rgb, 3, w, 3, h, 3 * w, kernel);
  blur_axis(image.rgb, 3, h, 3 * w, w, 3, kernel);
  blur_axis(image.transmittance, 1, w, 1, h, w, kernel);
  blur_axis(image.transmittance, 1, h, w, w, 1, kernel);
}

}  // namespace lfd::voxel
