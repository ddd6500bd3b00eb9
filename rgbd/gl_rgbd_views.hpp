#pragma once
// The GL twin of rgbd/rgbd_quilt.hpp (docs/rgbd.md "On the GPU"): an RGB-D frame texture to a
// quilt texture that gpu::GlInterlacer reads, in three fragment passes, one per CPU stage:
// resample (the halves read in place through their rectangles: no copy of the frame), warp (a
// gather: each output pixel finds the source pixels of its row that land on it and keeps the
// nearest, which is the CPU's scatter with its z-test) and fill (the background-side hole fill).
// Matches render_rgbd_quilt within the tolerance of tests/rgbd/gl_rgbd_views_test.cpp.
#include <epoxy/gl.h>

#include "gpu/gl/gl_objects.hpp"
#include "render/quilt_layout.hpp"
#include "rgbd/rgbd_options.hpp"
#include "util/default_display.hpp"
#include "util/image.hpp"

namespace lfd::rgbd {

// A frame texture the caller owns (a decoder's upload, say): a sampleable GL_TEXTURE_2D of
// width x height texels, rows bottom-up (GL's orientation: gpu::texture_from_image of the
// top-down image) unless top_down says otherwise, RGB in [0, 1] as read by texelFetch: the stored values, so not an sRGB
// internal format (GL would linearise the colour and the depth before the passes read them).
struct RgbdFrameTexture {
  GLuint id = 0;
  int width = 0;
  int height = 0;
  // True when texel row 0 is the picture's top row (a decoder's planes uploaded as they come),
  // so the caller need not flip the frame.
  bool top_down = false;
};

class GlRgbdViews {
 public:
  // Needs a current GL 4.5 context; compiles the three passes.
  GlRgbdViews();
  ~GlRgbdViews();
  GlRgbdViews(const GlRgbdViews&) = delete;
  GlRgbdViews& operator=(const GlRgbdViews&) = delete;

  // Writes the quilt of `frame` into `quilt` (layout.width x layout.height, any colour-
  // renderable format, rows bottom-up with view 0 in the bottom-left tile; black outside the
  // tiles; alpha 1). Keeps the intermediate textures between calls of the same tile size, so a
  // video frame costs three draws. Throws InputError for bad options, layout, frame size or a
  // quilt texture of the wrong size. Leaves the framebuffer binding and viewport as it found
  // them.
  void render(const RgbdFrameTexture& frame, const RgbdOptions& options,
              const render::QuiltLayout& layout, gpu::Texture& quilt,
              double view_cone_deg = kDefaultViewConeDeg);
  void render(const gpu::Texture& frame, const RgbdOptions& options,
              const render::QuiltLayout& layout, gpu::Texture& quilt,
              double view_cone_deg = kDefaultViewConeDeg);

 private:
  void ensure_intermediates(const render::QuiltLayout& layout);
  void draw_into(const gpu::Program& pass, const gpu::Texture& target, int width, int height) const;

  gpu::Program resample_, warp_, fill_;
  gpu::VertexArray triangle_;
  gpu::Framebuffer target_;
  gpu::Texture source_;  // tile-size RGBA32F: colour, depth
  gpu::Texture warped_;  // quilt-size RGBA32F: colour, landed depth (kHole where none)
  gpu::Texture shifts_;  // views x 1 R32F: each view's shift per unit z-ratio, in pixels
  GLuint sampler_ = 0;   // nearest, clamped: makes any caller's frame texture complete
};

// Convenience for files and tests: uploads the frame (top-down), renders on the GPU, reads the
// quilt back (top-down, 3 channels, like render_rgbd_quilt). Needs a current context.
ImageF render_rgbd_quilt_on_gpu(const ImageF& frame, const RgbdOptions& options,
                                const render::QuiltLayout& layout,
                                double view_cone_deg = kDefaultViewConeDeg);

}  // namespace lfd::rgbd
