// The one backend rule (lightfield/backend_choice.hpp) and "interlace on the GPU or the CPU"
// (lightfield/panel_interlacing.hpp): the names and their one-line error, the CPU needing no
// context, auto taking the GPU when there is one, and the GL panel within the GL interlacer's
// tolerance of the CPU reference (docs/gpu.md "The interlacing shader").
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "display/lens_model.hpp"
#include "interlace/interlacer.hpp"
#include "lightfield/backend_choice.hpp"
#include "lightfield/panel_interlacing.hpp"
#include "tests/support/quilt_layouts.hpp"
#include "tests/support/small_displays.hpp"
#include "util/error.hpp"

namespace lfd::lightfield {
namespace {

CpuFallbackNotice no_notice_expected() {
  return [](const std::string& reason) { ADD_FAILURE() << "unexpected fallback: " << reason; };
}

TEST(BackendChoice, NamesParseAndAnotherIsAOneLineErrorNamingTheField) {
  EXPECT_EQ(parse_backend_choice("cpu", "--backend"), BackendChoice::kCpu);
  EXPECT_EQ(parse_backend_choice("gl", "--backend"), BackendChoice::kGl);
  EXPECT_EQ(parse_backend_choice("auto", "--backend"), BackendChoice::kAuto);
  try {
    parse_backend_choice("vulkan", "backend");
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "backend: 'vulkan' is not cpu, gl or auto");
  }
}

TEST(BackendChoice, TheCpuOpensNoContext) {
  EXPECT_EQ(open_backend_context(BackendChoice::kCpu, no_notice_expected()), nullptr);
  EXPECT_EQ(backend_of(nullptr), Backend::kCpu);
}

TEST(BackendChoice, AutoTakesTheGpuWhenAContextCanBeMadeAndElseSaysWhy) {
  bool fell_back = false;
  const auto context =
      open_backend_context(BackendChoice::kAuto, [&](const std::string& reason) { fell_back = !reason.empty(); });
  EXPECT_EQ(context != nullptr, !fell_back);
  EXPECT_EQ(backend_of(context.get()), context ? Backend::kGl : Backend::kCpu);
}

// A quilt whose every view and channel holds its own smooth gradient.
ImageF varied_quilt(const render::QuiltLayout& q) {
  ImageF quilt(q.width, q.height, 3);
  for (int y = 0; y < q.height; ++y)
    for (int x = 0; x < q.width; ++x)
      for (int c = 0; c < 3; ++c)
        quilt.at(x, y, c) = float(0.5 + 0.5 * std::sin(0.05 * x + 0.07 * y + 1.3 * c));
  return quilt;
}

TEST(PanelInterlacing, TheCpuIsTheReferenceAndTheGpuAgreesWithin1Over255) {
  const display::LensModel lens(test::small_lkg_2k(0.1));
  const render::QuiltLayout q = test::quilt_layout(4, 2, 160, 100, 1.6);
  const ImageF quilt = varied_quilt(q);
  interlace::InterlaceOptions options;
  options.blend = interlace::ViewBlend::kLinear;
  const ImageF cpu = interlace_panel(quilt, q, lens, options, Backend::kCpu);
  EXPECT_EQ(cpu.pixels, interlace::interlace(quilt, q, lens, options).pixels);
  const auto context = open_backend_context(BackendChoice::kAuto, [](const std::string&) {});
  if (!context) GTEST_SKIP() << "no OpenGL 4.5 context";
  const ImageF gl = interlace_panel(quilt, q, lens, options, Backend::kGl);
  ASSERT_EQ(gl.pixels.size(), cpu.pixels.size());
  size_t within = 0;
  for (size_t i = 0; i < gl.pixels.size(); ++i) within += std::abs(gl.pixels[i] - cpu.pixels[i]) <= 1.0f / 255.0f;
  EXPECT_GE(double(within) / double(gl.pixels.size()), 0.999);
}

}  // namespace
}  // namespace lfd::lightfield
