#pragma once
// The direct panel pass on the GPU (docs/rendering.md "Direct panel rendering"; issue 24): the
// GL twin of interlace::render_direct_panel. A fragment pass over the panel composites the
// sweeping planes of a GlPlanes along each subpixel's own ray (gpu/shaders/direct_panel.frag.glsl),
// its view fraction from the shared lens_view.glsl (gpu/gl_lens_view.hpp, as the interlacer's).
// No quilt texture exists on this path.
#include <map>

#include <epoxy/gl.h>

#include "display/lens_model.hpp"
#include "gpu/gl_lens_view.hpp"
#include "gpu/gl_objects.hpp"
#include "gpu/gl_planes.hpp"
#include "interlace/direct_panel.hpp"
#include "render/quilt_geometry.hpp"
#include "util/image.hpp"

namespace lfd::gpu {

class GlDirectPanel {
 public:
  // Needs a current GL 4.5 context; uploads the lens model once. hardware_bilinear: bilinear
  // planes filtered by the texture unit (one fetch, its own weights) instead of four texelFetch
  // with the CPU's weights (docs/gpu.md "The direct pass on a GPU").
  explicit GlDirectPanel(const display::LensModel& lens, bool hardware_bilinear = true);

  // The panel of `planes` (their table on the GPU gives the count and depths) for the views of
  // `geometry` from `ref` into `panel` (screenW x screenH, colour-renderable, rows bottom-up;
  // alpha 1). Enqueues GPU work only. InputError for a panel of the wrong size.
  void run(const GlPlanes& planes, const render::QuiltGeometry& geometry, const render::ReferenceCamera& ref,
           const interlace::DirectPanelOptions& options, Texture& panel);
  // The same into the framebuffer bound now (a window's), viewport set to the panel size.
  void draw(const GlPlanes& planes, const render::QuiltGeometry& geometry, const render::ReferenceCamera& ref,
            const interlace::DirectPanelOptions& options);

  int panel_width() const { return panel_width_; }
  int panel_height() const { return panel_height_; }
  bool hardware_bilinear() const { return hardware_bilinear_; }

 private:
  const Program& program(render::PlaneFilter filter);

  display::DisplayCalibration calibration_;
  int panel_width_ = 0, panel_height_ = 0;
  bool hardware_bilinear_ = true;
  GlLensView lens_view_;
  Sampler linear_;  // hardware_bilinear's
  std::map<int, Program> programs_;
  VertexArray triangle_;
  Framebuffer target_;
};

// Convenience for tests: CPU planes uploaded (gpu::upload_planes), the direct pass on the GPU, the
// panel read back (float, top-down like interlace::render_direct_panel). Needs a current context.
ImageF direct_panel_on_gpu(const render::SweepingPlanes& planes, const render::QuiltGeometry& geometry,
                           const render::ReferenceCamera& ref, const display::LensModel& lens,
                           const interlace::DirectPanelOptions& options, bool hardware_bilinear = false);

}  // namespace lfd::gpu
