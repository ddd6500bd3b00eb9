#pragma once
// The lens model on the GPU (docs/gpu.md "Single precision"): the constants of
// gpu/panel/shaders/lens_view.glsl, the one GLSL definition of a subpixel's view fraction that the
// interlacing shader and the direct panel pass both include, taken from display::LensModel.
// The phase's large part is reduced on the CPU in double, so the shader runs in single
// precision (lens_view.glsl says why that is enough and where it is not).
#include <vector>

#include "display/lens_model.hpp"
#include "util/image.hpp"
#include "gpu/gl/gl_objects.hpp"

namespace lfd::gpu {

// The correction field w(u, v) is sampled bilinearly from a grid fine enough that the
// interpolation stays within this many lens periods (a view boundary moves by as much, so about
// 2 V times this fraction of subpixels may show the neighbouring view), with at most
// kMaxCorrectionGridPoints per axis (64 MiB).
inline constexpr double kCorrectionGridTolerancePeriods = 1e-6;
inline constexpr int kMaxCorrectionGridPoints = 4096;
// How far (lens periods) the shader's view fraction may lie from LensModel's in double, the
// correction grid's tolerance aside: the bound of lens_view.glsl's float arithmetic (5e-7) with
// a margin.
inline constexpr double kLensViewTolerance = 1e-6;

class GlLensView {
 public:
  // Needs a current GL 4.5 context; uploads the phase parts and the correction grid.
  explicit GlLensView(const display::LensModel& lens);

  // Sets lens_view.glsl's uniforms in `program` (once, after linking).
  void set_uniforms(const Program& program) const;
  // What lens_view.glsl reads, for the declaration of a program that includes it, after the
  // program's own: the correction grid (kLensCorrectionUnit) and the phase parts
  // (kLensPhasePartsBinding; gpu/panel/shaders/lens_view_io.h).
  static std::vector<Binding> bindings_after(std::vector<Binding> program_own);
  // Binds both through `program`, which declared them with bindings_after.
  void bind(const Program& program) const;

  // w(u, v) at grid point (i, j) = (i / (width - 1), j / (height - 1)), R32F; 2 x 2 zeros
  // without a correction field.
  const Texture& correction_grid() const { return correction_; }
  // column[x] then row[j] as uploaded (lens_view.glsl).
  static std::vector<float> phase_parts(const display::LensModel& lens);

 private:
  int width_ = 0, height_ = 0;
  bool inv_view_ = false, has_correction_ = false;
  std::vector<float> offsets_, phases_;  // per class and channel: (du, dv), (du + dv tilt) pitch'
  Texture correction_;
  Buffer phase_parts_;
};

// The view fraction of every channel of panel rows [first_row, first_row + rows) (top-down) as
// lens_view.glsl computes it: RGB = the fractions of R, G, B, rows top-down. For measuring the
// shaders' precision against LensModel::subpixel_view_fraction (tests, docs/gpu.md). Needs a
// current context.
ImageF view_fractions_on_gpu(const display::LensModel& lens, int first_row, int rows);

}  // namespace lfd::gpu
