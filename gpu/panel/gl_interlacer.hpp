#pragma once
// The interlacing shader (docs/gpu.md "The interlacing shader"): the GLSL twin of the CPU reference
// interlace::Interlacer, reading a quilt texture and writing the panel, so a frame can go
// scene -> quilt -> panel on the GPU with no CPU round trip. Its constants come from
// display::LensModel, the one definition of the lens phase, view fraction and view index; the
// shader (gpu/panel/shaders/interlace.frag.glsl) takes a subpixel's view fraction from
// gpu/panel/shaders/lens_view.glsl (gpu/panel/gl_lens_view.hpp), in single precision. It matches interlace::interlace within 1/255 on all but a negligible fraction of
// subpixels (tests/gpu/gl_interlacer_test.cpp, docs/rendering.md).
#include <map>

#include <epoxy/gl.h>

#include "display/lens_model.hpp"
#include "gpu/panel/gl_lens_view.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "interlace/interlacer.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::gpu {

// Which stage interlace() runs (docs/gpu.md "The interlacing shader"): a compute pass writing
// the panel texture as an image (the offscreen paths: no rasteriser, so it runs on every SM of
// a GPU whose graphics pipeline is narrower than its compute), or the fragment pass into a
// framebuffer (what draw() into a window always uses). Both compute interlace_pixel.glsl.
enum class InterlacePass { kFragment, kCompute };

class GlInterlacer {
 public:
  // Needs a current GL 4.5 context. Uploads the per-display constants and the correction grid
  // once. Throws InputError if the layout is unusable (as the CPU interlacer does).
  GlInterlacer(const display::LensModel& lens, const render::QuiltLayout& layout,
               interlace::InterlaceOptions options = {}, InterlacePass pass = InterlacePass::kFragment);

  // quilt: layout.width x layout.height, rows bottom-up as rendered (view 0 in the bottom-left
  // tile), any sampleable format. panel: screenW x screenH, RGBA8, RGBA16F or RGBA32F (the
  // fragment pass: any colour-renderable format), rows bottom-up; alpha is 1. Throws InputError
  // on wrong sizes. Enqueues GPU work only; the panel is ready for texture fetches, image loads
  // and read-backs after it.
  void interlace(const Texture& quilt, Texture& panel);
  // Draws the panel into the framebuffer bound now (a window's, say) with the viewport set to
  // the panel size; blending, depth and scissor tests are switched off. Always the fragment pass.
  void draw(const Texture& quilt) const;

  InterlacePass pass() const { return pass_; }

  int panel_width() const { return panel_width_; }
  int panel_height() const { return panel_height_; }
  // w(u, v) at grid point (i, j) = (u, v) = (i / (width - 1), j / (height - 1)), R32F;
  // 2 x 2 zeros without a correction field.
  const Texture& correction_grid() const { return lens_view_.correction_grid(); }

 private:
  void check_quilt(const Texture& quilt) const;
  void set_uniforms(const Program& program) const;
  const Program& compute_program(GLenum panel_format);

  render::QuiltLayout layout_;
  interlace::InterlaceOptions options_;
  InterlacePass pass_;
  display::DisplayCalibration calibration_;
  int panel_width_ = 0, panel_height_ = 0;
  Program program_;
  std::map<GLenum, Program> compute_programs_;  // by the panel's format
  VertexArray triangle_;
  Framebuffer target_;
  GlLensView lens_view_;
};

// A top-down image as an RGBA32F texture with rows bottom-up (GL's orientation, so a quilt
// image becomes what a renderer writes); one channel is replicated into RGB, alpha is 1.
Texture texture_from_image(const ImageF& image);
// The RGB of a texture as a top-down image.
ImageF image_from_texture(const Texture& texture);

// Convenience for files and tests: uploads the quilt, interlaces on the GPU (the compute pass
// unless told), reads the panel back (float, top-down like interlace::interlace). Needs a
// current context.
ImageF interlace_on_gpu(const ImageF& quilt, const render::QuiltLayout& layout,
                        const display::LensModel& lens,
                        const interlace::InterlaceOptions& options = {},
                        InterlacePass pass = InterlacePass::kCompute);

}  // namespace lfd::gpu
