#include "gpu/panel/gl_lens_view.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "gpu/panel/shaders/interlace.vert.glsl.hpp"
#include "gpu/panel/shaders/lens_view_io.h"
#include "gpu/panel/shaders/lens_view_probe.frag.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

// The shader looks subpixel offsets up by pixel class (x mod 2) + 2 (j mod 4), j bottom-up.

// LensModel::subpixel_uv - pixel_uv for each pixel class and channel, taken from LensModel
// itself so the shader holds no rule of its own for BGR panels or Gen3 cells.
std::vector<double> subpixel_offset_table(const display::LensModel& lens) {
  const int h = lens.calibration().screen_h;
  std::vector<double> table;
  for (int jm = 0; jm < kLensPixelClassesY; ++jm)
    for (int xm = 0; xm < kLensPixelClassesX; ++xm)
      for (int c = 0; c < 3; ++c) {
        const display::ScreenUV p = lens.pixel_uv(xm, h - 1 - jm);
        const display::ScreenUV s = lens.subpixel_uv(xm, h - 1 - jm, c);
        table.push_back(s.u - p.u);
        table.push_back(s.v - p.v);
      }
  // Guard the period the table assumes: every cell pattern of lens_model.cpp repeats within
  // 2 x 4 pixels. A new pattern with a longer period must fail here, not alias on the GPU.
  for (int j = 0; j < 3 * kLensPixelClassesY; ++j)
    for (int x = 0; x < 3 * kLensPixelClassesX; ++x)
      for (int c = 0; c < 3; ++c) {
        const int row = h - 1 - j;
        const size_t k = size_t(((x % kLensPixelClassesX) + kLensPixelClassesX * (j % kLensPixelClassesY)) * 3 + c) * 2;
        const display::ScreenUV p = lens.pixel_uv(x, row), s = lens.subpixel_uv(x, row, c);
        if (std::abs(p.u + table[k] - s.u) > 1e-12 || std::abs(p.v + table[k + 1] - s.v) > 1e-12)
          throw std::logic_error("GlLensView: the subpixel layout does not repeat every 2x4 pixels");
      }
  return table;
}

// Largest |second difference| of the control points along one axis.
double max_second_difference(const display::CorrectionField& w, bool along_u) {
  const auto& c = w.coefficients();
  double m = 0;
  for (int j = 0; j < w.ny(); ++j)
    for (int i = 0; i < w.nx(); ++i) {
      const int di = along_u ? 1 : 0, dj = along_u ? 0 : 1;
      if (i + 2 * di >= w.nx() || j + 2 * dj >= w.ny()) continue;
      const auto at = [&](int k) { return c[size_t(j + k * dj) * w.nx() + size_t(i + k * di)]; };
      m = std::max(m, std::abs(at(0) - 2 * at(1) + at(2)));
    }
  return m;
}

// Grid points along one axis for bilinear interpolation within `tolerance`: the error is at
// most h^2/8 max|w''|, and a uniform cubic B-spline with n control points has
// |w''| <= (n - 3)^2 max|second difference|. Capped at kMaxCorrectionGridPoints (the cap is
// reached only by fields far rougher than the solver's smoothness prior gives).
int grid_points(int control_points, double second_difference, double tolerance) {
  const double curvature = double(control_points - 3) * (control_points - 3) * second_difference;
  const double intervals = std::ceil(std::sqrt(curvature / (8.0 * tolerance)));
  return int(std::clamp(intervals, 1.0, double(kMaxCorrectionGridPoints - 1))) + 1;
}

// w(u, v) evaluated on the grid the shader interpolates (point i at u = i / (points - 1)), or a
// 2 x 2 grid of zeros without a field.
Texture correction_grid_texture(const display::LensModel& lens) {
  const display::CorrectionField& w = lens.correction();
  if (w.empty()) {
    const float zeros[4] = {0, 0, 0, 0};
    Texture grid(GL_R32F, 2, 2);
    upload_texture_2d(grid, 0, 0, 2, 2, GL_RED, GL_FLOAT, zeros);
    return grid;
  }
  // Half the tolerance per axis.
  const double tolerance = kCorrectionGridTolerancePeriods / 2;
  const int gw = grid_points(w.nx(), max_second_difference(w, true), tolerance);
  const int gh = grid_points(w.ny(), max_second_difference(w, false), tolerance);
  std::vector<float> values(size_t(gw) * gh);
#pragma omp parallel for
  for (int j = 0; j < gh; ++j)
    for (int i = 0; i < gw; ++i)
      values[size_t(j) * gw + i] = float(w(double(i) / (gw - 1), double(j) / (gh - 1)));
  Texture grid(GL_R32F, gw, gh);
  upload_texture_2d(grid, 0, 0, gw, gh, GL_RED, GL_FLOAT, values.data());
  return grid;
}

// x - floor(x) in double: the phase parts the shader adds in float.
double frac(double x) { return x - std::floor(x); }

}  // namespace

std::vector<float> GlLensView::phase_parts(const display::LensModel& lens) {
  const auto& cal = lens.calibration();
  const double pitch = lens.pitch_periods(), tilt = lens.tilt();
  std::vector<float> parts;
  parts.reserve(size_t(cal.screen_w) + size_t(cal.screen_h));
  // The terms of LensModel::phase at pixel centre (x, j): (x + 1/2) / W pitch' and
  // (j + 1/2) / H tilt pitch' - center (v = 1 - (row + 1/2) / H = (j + 1/2) / H), reduced.
  for (int x = 0; x < cal.screen_w; ++x) parts.push_back(float(frac((x + 0.5) / cal.screen_w * pitch)));
  for (int j = 0; j < cal.screen_h; ++j)
    parts.push_back(float(frac((j + 0.5) / cal.screen_h * tilt * pitch - cal.center_periods)));
  return parts;
}

GlLensView::GlLensView(const display::LensModel& lens)
    : width_(lens.calibration().screen_w),
      height_(lens.calibration().screen_h),
      inv_view_(lens.calibration().inv_view),
      has_correction_(!lens.correction().empty()),
      correction_(correction_grid_texture(lens)) {
  const std::vector<double> table = subpixel_offset_table(lens);
  for (size_t k = 0; k + 1 < table.size(); k += 2) {
    offsets_.push_back(float(table[k]));
    offsets_.push_back(float(table[k + 1]));
    phases_.push_back(float((table[k] + table[k + 1] * lens.tilt()) * lens.pitch_periods()));
  }
  const std::vector<float> parts = phase_parts(lens);
  phase_parts_ = Buffer(parts.size() * sizeof(float), parts.data());
  check_gl("uploading the lens model");
}

void GlLensView::set_uniforms(const Program& program) const {
  const GLuint p = program.id();
  const auto at = [&](const char* name) { return program.uniform(name); };
  glProgramUniform2i(p, at("panel_size"), width_, height_);
  glProgramUniform1i(p, at("inv_view"), inv_view_ ? 1 : 0);
  glProgramUniform2fv(p, at("subpixel_offset"), GLsizei(offsets_.size() / 2), offsets_.data());
  glProgramUniform1fv(p, at("subpixel_phase"), GLsizei(phases_.size()), phases_.data());
  glProgramUniform1i(p, at("has_correction"), has_correction_ ? 1 : 0);
  glProgramUniform2i(p, at("correction_grid"), correction_.width(), correction_.height());
  check_gl("setting the lens model's uniforms");
}

std::vector<Binding> GlLensView::bindings_after(std::vector<Binding> program_own) {
  program_own.push_back(texture("lens_correction", kLensCorrectionUnit));
  program_own.push_back(storage_buffer("lens_phase_parts", kLensPhasePartsBinding, Access::read));
  return program_own;
}

void GlLensView::bind(const Program& program) const {
  program.bind("lens_correction", correction_);
  program.bind("lens_phase_parts", phase_parts_);
}

ImageF view_fractions_on_gpu(const display::LensModel& lens, int first_row, int rows) {
  const auto& cal = lens.calibration();
  if (first_row < 0 || rows < 1 || first_row + rows > cal.screen_h)
    throw_input_error("view fractions: rows {}..{} are outside the panel's {}", first_row, first_row + rows - 1,
                      cal.screen_h);
  const GlLensView view(lens);
  const Program program("lens view probe",
                        {{GL_VERTEX_SHADER, interlace_vert_glsl}, {GL_FRAGMENT_SHADER, lens_view_probe_frag_glsl}}, {},
                        GlLensView::bindings_after({}));
  view.set_uniforms(program);
  // The band's lowest row bottom-up: top-down rows first_row .. first_row + rows - 1.
  glProgramUniform1i(program.id(), program.uniform("first_j"), cal.screen_h - first_row - rows);
  Texture band(GL_RGBA32F, cal.screen_w, rows);
  Framebuffer target;
  target.attach(0, band);
  target.finish(1);
  const VertexArray triangle;
  glBindFramebuffer(GL_FRAMEBUFFER, target.id());
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, cal.screen_w, rows);
  program.use();
  view.bind(program);
  glBindVertexArray(triangle.id());
  program.draw_arrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("probing the lens view");
  const std::vector<float> rgba = read_texture_rgba(band);
  ImageF out(cal.screen_w, rows, 3);
  for (int y = 0; y < rows; ++y) {
    const float* src = rgba.data() + size_t(rows - 1 - y) * size_t(cal.screen_w) * 4;
    for (int x = 0; x < cal.screen_w; ++x)
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = src[size_t(x) * 4 + size_t(c)];
  }
  return out;
}

}  // namespace lfd::gpu
