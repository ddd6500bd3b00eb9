#pragma once
// The direct panel pass on the GPU (docs/rendering.md "Direct panel rendering"; issues 24, 33):
// the GL twin of interlace::render_direct_panel. It composites the sweeping planes of a GlPlanes
// along each subpixel's own ray (gpu/panel/shaders/direct_panel_rays.glsl), its view fraction from the
// shared lens_view.glsl (gpu/panel/gl_lens_view.hpp, as the interlacer's): a compute pass over panel
// tiles into a texture (direct_panel.comp.glsl: run(), the default) or a fragment pass into a
// framebuffer (direct_panel.frag.glsl: draw(), and run() when asked). No quilt texture exists on
// this path.
#include <map>
#include <utility>

#include <epoxy/gl.h>

#include "display/lens_model.hpp"
#include "gpu/panel/gl_lens_view.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "interlace/direct_panel.hpp"
#include "render/quilt_geometry.hpp"
#include "util/image.hpp"

namespace lfd::gpu {

// The stage run() uses (docs/gpu.md "The direct panel pass on the GPU"): a compute pass, a work
// group per tile of the panel (no rasteriser: every SM of a GPU whose graphics pipeline is
// narrower than its compute), or the fragment pass. Both composite with direct_panel_rays.glsl.
// kComputePlaneMajor: the compute pass with a barrier after every plane, so the whole tile reads
// plane k before plane k + 1 (the swizzle's order); the same image, for measuring the order.
enum class DirectPanelPass { kFragment, kCompute, kComputePlaneMajor };

class GlDirectPanel {
 public:
  // Needs a current GL 4.5 context; uploads the lens model once. hardware_bilinear: bilinear
  // planes filtered by the texture unit (one fetch, its own weights) instead of four texelFetch
  // with the CPU's weights (docs/gpu.md "The direct pass on a GPU").
  explicit GlDirectPanel(const display::LensModel& lens, bool hardware_bilinear = true,
                         DirectPanelPass pass = DirectPanelPass::kCompute);

  // The panel of `planes` (their table on the GPU gives the count and depths) for the views of
  // `geometry` from `ref` into `panel` (screenW x screenH, rows bottom-up; alpha 1; RGBA8,
  // RGBA16F or RGBA32F for the compute pass, any colour-renderable format for the fragment
  // pass). Enqueues GPU work only. InputError for a panel of the wrong size.
  void run(const GlPlanes& planes, const render::QuiltGeometry& geometry, const render::ReferenceCamera& ref,
           const interlace::DirectPanelOptions& options, Texture& panel);
  // The same into the framebuffer bound now (a window's), viewport set to the panel size: always
  // the fragment pass.
  void draw(const GlPlanes& planes, const render::QuiltGeometry& geometry, const render::ReferenceCamera& ref,
            const interlace::DirectPanelOptions& options);

  int panel_width() const { return panel_width_; }
  int panel_height() const { return panel_height_; }
  bool hardware_bilinear() const { return hardware_bilinear_; }
  DirectPanelPass pass() const { return pass_; }

 private:
  // The fragment stage (panel_format 0) or the compute stage writing that format.
  const Program& program(render::PlaneFilter filter, GLenum panel_format = 0);
  // Sets the uniforms of the frame and binds the planes, the table and the lens view.
  const Program& prepare(const GlPlanes& planes, const render::QuiltGeometry& geometry,
                         const render::ReferenceCamera& ref, const interlace::DirectPanelOptions& options,
                         GLenum panel_format);

  display::DisplayCalibration calibration_;
  int panel_width_ = 0, panel_height_ = 0;
  bool hardware_bilinear_ = true;
  DirectPanelPass pass_ = DirectPanelPass::kCompute;
  GlLensView lens_view_;
  Sampler linear_;  // hardware_bilinear's
  std::map<std::pair<int, GLenum>, Program> programs_;
  VertexArray triangle_;
  Framebuffer target_;
};

// Convenience for tests: CPU planes uploaded (gpu::upload_planes), the direct pass on the GPU, the
// panel read back (float, top-down like interlace::render_direct_panel). Needs a current context.
ImageF direct_panel_on_gpu(const render::SweepingPlanes& planes, const render::QuiltGeometry& geometry,
                           const render::ReferenceCamera& ref, const display::LensModel& lens,
                           const interlace::DirectPanelOptions& options, bool hardware_bilinear = false,
                           DirectPanelPass pass = DirectPanelPass::kCompute);

}  // namespace lfd::gpu
