#pragma once
// The interlacing shader (docs/gpu.md "The interlacing shader"): the GLSL twin of the CPU reference
// interlace::Interlacer, reading a quilt texture and writing the panel, so a frame can go
// scene -> quilt -> panel on the GPU with no CPU round trip. Its constants come from
// display::LensModel, the one definition of the lens phase, view fraction and view index; the
// shader (gpu/shaders/interlace.frag.glsl) takes a subpixel's view fraction from
// gpu/shaders/lens_view.glsl (gpu/gl_lens_view.hpp), in single precision. It matches interlace::interlace within 1/255 on all but a negligible fraction of
// subpixels (tests/gpu/gl_interlacer_test.cpp, docs/rendering.md).
#include <epoxy/gl.h>

#include "display/lens_model.hpp"
#include "gpu/gl_lens_view.hpp"
#include "gpu/gl_objects.hpp"
#include "interlace/interlacer.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::gpu {

class GlInterlacer {
 public:
  // Needs a current GL 4.5 context. Uploads the per-display constants and the correction grid
  // once. Throws InputError if the layout is unusable (as the CPU interlacer does).
  GlInterlacer(const display::LensModel& lens, const render::QuiltLayout& layout,
               interlace::InterlaceOptions options = {});

  // quilt: layout.width x layout.height, rows bottom-up as rendered (view 0 in the bottom-left
  // tile), any sampleable format. panel: screenW x screenH, any colour-renderable format
  // (RGBA8, RGBA16F, RGBA32F), rows bottom-up; alpha is 1. Throws InputError on wrong sizes.
  void interlace(const Texture& quilt, Texture& panel);
  // Draws the panel into the framebuffer bound now (a window's, say) with the viewport set to
  // the panel size; blending, depth and scissor tests are switched off.
  void draw(const Texture& quilt) const;

  int panel_width() const { return panel_width_; }
  int panel_height() const { return panel_height_; }
  // w(u, v) at grid point (i, j) = (u, v) = (i / (width - 1), j / (height - 1)), R32F;
  // 2 x 2 zeros without a correction field.
  const Texture& correction_grid() const { return lens_view_.correction_grid(); }

 private:
  void check_quilt(const Texture& quilt) const;

  render::QuiltLayout layout_;
  int panel_width_ = 0, panel_height_ = 0;
  Program program_;
  VertexArray triangle_;
  Framebuffer target_;
  GlLensView lens_view_;
};

// A top-down image as an RGBA32F texture with rows bottom-up (GL's orientation, so a quilt
// image becomes what a renderer writes); one channel is replicated into RGB, alpha is 1.
Texture texture_from_image(const ImageF& image);
// The RGB of a texture as a top-down image.
ImageF image_from_texture(const Texture& texture);

// Convenience for files and tests: uploads the quilt, interlaces on the GPU, reads the panel
// back (float, top-down like interlace::interlace). Needs a current context.
ImageF interlace_on_gpu(const ImageF& quilt, const render::QuiltLayout& layout,
                        const display::LensModel& lens,
                        const interlace::InterlaceOptions& options = {});

}  // namespace lfd::gpu
