#include "bench/gl_bench_target.hpp"

#include "gpu/gl_per_view_renderer.hpp"

namespace lfd::bench {

gpu::Texture& GlBenchTarget::quilt(const render::QuiltLayout& layout) {
  if (quilt_.width() != layout.width || quilt_.height() != layout.height)
    quilt_ = gpu::Texture(GL_RGBA8, layout.width, layout.height);
  return quilt_;
}

const ImageF& GlBenchTarget::read_quilt() {
  image_ = gpu::read_image_top_down(quilt_, 3);
  return image_;
}

void GlBenchTarget::reset_peak_memory() { gpu::reset_gpu_peak(); }
size_t GlBenchTarget::peak_memory_bytes() { return gpu::gpu_bytes_peak(); }

}  // namespace lfd::bench
