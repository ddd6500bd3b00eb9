#include "gpu/gl_interlacer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "gpu/shaders/interlace.frag.glsl.hpp"
#include "gpu/shaders/interlace.vert.glsl.hpp"
#include "util/error.hpp"

namespace lfd::gpu {
namespace {

// The shader looks subpixel offsets up by pixel class (x mod 2) + 2 (j mod 4), j bottom-up.
constexpr int kClassesX = 2, kClassesY = 4;

// LensModel::subpixel_uv - pixel_uv for each pixel class and channel, taken from LensModel
// itself so the shader holds no rule of its own for BGR panels or Gen3 cells.
std::vector<double> subpixel_offset_table(const display::LensModel& lens) {
  const int h = lens.calibration().screen_h;
  std::vector<double> table;
  for (int jm = 0; jm < kClassesY; ++jm)
    for (int xm = 0; xm < kClassesX; ++xm)
      for (int c = 0; c < 3; ++c) {
        const display::ScreenUV p = lens.pixel_uv(xm, h - 1 - jm);
        const display::ScreenUV s = lens.subpixel_uv(xm, h - 1 - jm, c);
        table.push_back(s.u - p.u);
        table.push_back(s.v - p.v);
      }
  // Guard the period the table assumes: every cell pattern of lens_model.cpp repeats within
  // 2 x 4 pixels. A new pattern with a longer period must fail here, not alias on the GPU.
  for (int j = 0; j < 3 * kClassesY; ++j)
    for (int x = 0; x < 3 * kClassesX; ++x)
      for (int c = 0; c < 3; ++c) {
        const int row = h - 1 - j;
        const size_t k = size_t(((x % kClassesX) + kClassesX * (j % kClassesY)) * 3 + c) * 2;
        const display::ScreenUV p = lens.pixel_uv(x, row), s = lens.subpixel_uv(x, row, c);
        if (std::abs(p.u + table[k] - s.u) > 1e-12 || std::abs(p.v + table[k + 1] - s.v) > 1e-12)
          throw std::logic_error("GlInterlacer: the subpixel layout does not repeat every 2x4 pixels");
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
    glTextureSubImage2D(grid.id(), 0, 0, 0, 2, 2, GL_RED, GL_FLOAT, zeros);
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
  glTextureSubImage2D(grid.id(), 0, 0, 0, gw, gh, GL_RED, GL_FLOAT, values.data());
  return grid;
}

}  // namespace

GlInterlacer::GlInterlacer(const display::LensModel& lens, const render::QuiltLayout& layout,
                           interlace::InterlaceOptions options)
    : layout_(layout),
      panel_width_(lens.calibration().screen_w),
      panel_height_(lens.calibration().screen_h),
      program_("interlace", {{GL_VERTEX_SHADER, interlace_vert_glsl},
                             {GL_FRAGMENT_SHADER, interlace_frag_glsl}}),
      correction_(correction_grid_texture(lens)) {
  layout_.check("quilt");
  const auto& cal = lens.calibration();
  const GLuint p = program_.id();
  const auto at = [&](const char* name) { return program_.uniform(name); };

  glProgramUniform2i(p, at("panel_size"), cal.screen_w, cal.screen_h);
  glProgramUniform2d(p, at("inv_panel_size"), 1.0 / cal.screen_w, 1.0 / cal.screen_h);
  glProgramUniform1d(p, at("pitch_periods"), lens.pitch_periods());
  glProgramUniform1d(p, at("tilt"), lens.tilt());
  glProgramUniform1d(p, at("center_periods"), cal.center_periods);
  glProgramUniform1i(p, at("inv_view"), cal.inv_view ? 1 : 0);
  const std::vector<double> offsets = subpixel_offset_table(lens);
  glProgramUniform2dv(p, at("subpixel_offset"), GLsizei(offsets.size() / 2), offsets.data());
  glProgramUniform1i(p, at("has_correction"), lens.correction().empty() ? 0 : 1);
  glProgramUniform2i(p, at("correction_grid"), correction_.width(), correction_.height());

  glProgramUniform1i(p, at("views"), layout_.views);
  glProgramUniform1i(p, at("quilt_cols"), layout_.cols);
  glProgramUniform2i(p, at("tile_size"), layout_.tile_width(), layout_.tile_height());
  // Interlacer::sample_for's aspect fit (looking-glass.md 3.8) as a scale of (u - 0.5, v - 0.5).
  const double display_aspect = double(cal.screen_w) / cal.screen_h;
  const double quilt_aspect = layout_.aspect;
  const bool fit_x = (display_aspect >= quilt_aspect && !options.overscan) ||
                     (display_aspect <= quilt_aspect && options.overscan);
  glProgramUniform2d(p, at("aspect_scale"), fit_x ? display_aspect / quilt_aspect : 1.0,
                     fit_x ? 1.0 : quilt_aspect / display_aspect);
  glProgramUniform1i(p, at("invert_views"), options.invert_views ? 1 : 0);
  glProgramUniform1i(p, at("linear_blend"), options.blend == interlace::ViewBlend::kLinear);
  glProgramUniform1f(p, at("fringe"), float(cal.fringe));
  check_gl("setting up the interlacing shader");
}

void GlInterlacer::check_quilt(const Texture& quilt) const {
  if (quilt.width() != layout_.width || quilt.height() != layout_.height || quilt.layers())
    throw_input_error("quilt: texture is {}x{}{} but the layout says {}x{}", quilt.width(),
                      quilt.height(), quilt.layers() ? " (an array)" : "", layout_.width,
                      layout_.height);
}

void GlInterlacer::draw(const Texture& quilt) const {
  check_quilt(quilt);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, panel_width_, panel_height_);
  program_.use();
  glBindTextureUnit(0, quilt.id());
  glBindTextureUnit(1, correction_.id());
  glBindVertexArray(triangle_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  check_gl("interlacing");
}

void GlInterlacer::interlace(const Texture& quilt, Texture& panel) {
  if (panel.width() != panel_width_ || panel.height() != panel_height_ || panel.layers())
    throw_input_error("panel: texture is {}x{} but the display is {}x{}", panel.width(),
                      panel.height(), panel_width_, panel_height_);
  target_.attach(0, panel);
  target_.finish(1);
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  draw(quilt);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

Texture texture_from_image(const ImageF& image) {
  if (image.channels != 1 && image.channels != 3 && image.channels != 4)
    throw std::invalid_argument("texture_from_image: 1, 3 or 4 channels");
  std::vector<float> rgba(size_t(image.width) * image.height * 4);
  for (int y = 0; y < image.height; ++y) {
    const float* src = image.row(image.height - 1 - y);  // GL rows run bottom-up
    float* dst = rgba.data() + size_t(y) * image.width * 4;
    for (int x = 0; x < image.width; ++x, src += image.channels, dst += 4) {
      const bool grey = image.channels == 1;
      dst[0] = src[0];
      dst[1] = src[grey ? 0 : 1];
      dst[2] = src[grey ? 0 : 2];
      dst[3] = image.channels == 4 ? src[3] : 1.f;
    }
  }
  Texture texture(GL_RGBA32F, image.width, image.height);
  glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_FLOAT,
                      rgba.data());
  check_gl("uploading an image");
  return texture;
}

ImageF image_from_texture(const Texture& texture) {
  const std::vector<float> rgba = read_texture_rgba(texture);
  ImageF image(texture.width(), texture.height(), 3);
  for (int y = 0; y < image.height; ++y) {
    const float* src = rgba.data() + size_t(image.height - 1 - y) * image.width * 4;
    float* dst = image.row(y);
    for (int x = 0; x < image.width; ++x, src += 4, dst += 3) std::copy(src, src + 3, dst);
  }
  return image;
}

ImageF interlace_on_gpu(const ImageF& quilt, const render::QuiltLayout& layout,
                        const display::LensModel& lens, const interlace::InterlaceOptions& options) {
  if (quilt.width != layout.width || quilt.height != layout.height)
    throw_input_error("quilt: image is {}x{} but the layout says {}x{}", quilt.width,
                      quilt.height, layout.width, layout.height);
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
  const auto& cal = lens.calibration();
  if (std::max(quilt.width, quilt.height) > max_size ||
      std::max(cal.screen_w, cal.screen_h) > max_size)
    throw_input_error("quilt {}x{} or panel {}x{}: larger than this GL's textures ({} pixels)",
                      quilt.width, quilt.height, cal.screen_w, cal.screen_h, max_size);
  GlInterlacer interlacer(lens, layout, options);
  const Texture quilt_texture = texture_from_image(quilt);
  Texture panel(GL_RGBA32F, cal.screen_w, cal.screen_h);
  interlacer.interlace(quilt_texture, panel);
  return image_from_texture(panel);
}

}  // namespace lfd::gpu
