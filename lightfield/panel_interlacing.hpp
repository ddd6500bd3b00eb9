#pragma once
// The one rule for "interlace on the GPU or the CPU" (`lfd render --panel`, `lfd interlace`,
// `lfd record --panel`, Python's `lfd.interlace`, the demo): the GL interlacing shader where the
// quilt was rendered on the GPU, the CPU reference otherwise. The two agree to within 1/255
// (docs/gpu.md "The interlacing shader"), so the choice changes the speed, not the figures.
#include "display/lens_model.hpp"
#include "interlace/interlacer.hpp"
#include "lightfield/renderer_options.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::lightfield {

// The panel of `quilt` for the display of `lens` (float, top row first): on the GPU for
// Backend::kGl (gpu::interlace_on_gpu, the compute pass; a GL context must be current on this
// thread), interlace::interlace on the CPU for Backend::kCpu.
ImageF interlace_panel(const ImageF& quilt, const render::QuiltLayout& layout, const display::LensModel& lens,
                       const interlace::InterlaceOptions& options, Backend backend);

}  // namespace lfd::lightfield
