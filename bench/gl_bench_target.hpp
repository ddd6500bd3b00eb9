#pragma once
// What the GL benchmark renderers (gl_quilt_renderer, voxel_quilt_renderer) share: the
// headless context they render in, the quilt as displayed (RGBA8) that they render into and
// read back on demand, and GPU memory as the memory they report.
#include <cstddef>
#include <string>

#include "gpu/gl_context.hpp"
#include "gpu/gl_objects.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::bench {

class GlBenchTarget {
 public:
  const gpu::GlInfo& info() const { return context_.info(); }
  // The quilt texture, reallocated when the layout's size changes.
  gpu::Texture& quilt(const render::QuiltLayout& layout);
  // Reads the quilt back (top row first, RGB).
  const ImageF& read_quilt();

  static std::string memory_kind() { return "GPU memory (lfd's buffers and textures)"; }
  static void reset_peak_memory();
  static size_t peak_memory_bytes();

 private:
  gpu::HeadlessContext context_;  // first: everything after it needs the context
  gpu::Texture quilt_;
  ImageF image_;
};

}  // namespace lfd::bench
