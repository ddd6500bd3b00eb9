#include "lightfield/panel_interlacing.hpp"

#include "gpu/panel/gl_interlacer.hpp"

namespace lfd::lightfield {

ImageF interlace_panel(const ImageF& quilt, const render::QuiltLayout& layout, const display::LensModel& lens,
                       const interlace::InterlaceOptions& options, Backend backend) {
  return backend == Backend::kGl ? gpu::interlace_on_gpu(quilt, layout, lens, options)
                                 : interlace::interlace(quilt, layout, lens, options);
}

}  // namespace lfd::lightfield
