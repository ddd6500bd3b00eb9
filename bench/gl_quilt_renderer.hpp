#pragma once
// The GL backend of `lfd bench render`: the per-view quilt and G2LF of gpu/ on a headless EGL
// context (NVIDIA's EGL device, or llvmpipe here). Frames are timed to glFinish, so the wall
// time of a call is the GPU frame; quilts are read back only in read_quilt (untimed).
#include <memory>

#include "bench/quilt_renderer.hpp"

namespace lfd::bench {

// Throws gpu::GlUnavailable (exit 2, one line) when no OpenGL 4.5 core context can be made.
std::unique_ptr<QuiltRenderer> make_gl_quilt_renderer();

}  // namespace lfd::bench
