// Single precision in the shaders (gpu/panel/shaders/lens_view.glsl, docs/gpu.md "Single precision"):
// over whole panels of real calibrations and templates up to 8K (32" Gen2 and Gen3), the view
// fraction every subpixel gets on the GPU against LensModel's in double. The proof is the bound:
// |f_GPU - f_CPU| <= kLensViewTolerance everywhere (on the circle: across the wrap at 0/1 only
// the clamps differ), so a subpixel can show another view than on the CPU only when its phase lies
// within that tolerance of a view boundary; those ties are counted at the display's view count.
#include "gpu/panel/gl_lens_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "display/visual_json.hpp"
#include "gpu/gl/gl_context.hpp"
#include "tests/test_data.hpp"

namespace lfd::gpu {
namespace {

struct Precision {
  double max_deviation = 0;  // |f_GPU - f_CPU| on the circle, the clamp at the wrap aside
  size_t wraps = 0;          // subpixels on opposite clamps (phase within the tolerance of an integer)
  size_t view_differs = 0;   // at the display's view count
  size_t view_differs_not_tie = 0;
  size_t subpixels = 0;
};

bool at_wrap(double f, double tolerance) { return f <= 1e-5 + tolerance || f >= 0.999999 - tolerance; }

Precision measure(const display::LensModel& lens, int views) {
  const auto& cal = lens.calibration();
  Precision p;
  const int band = 256;
  for (int first = 0; first < cal.screen_h; first += band) {
    const int rows = std::min(band, cal.screen_h - first);
    const ImageF gpu = view_fractions_on_gpu(lens, first, rows);
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < cal.screen_w; ++x)
        for (int c = 0; c < 3; ++c) {
          const int row = first + y;
          const double f_cpu = lens.subpixel_view_fraction(x, row, c), f_gpu = gpu.at(x, y, c);
          double d = std::abs(f_gpu - f_cpu);
          d = std::min(d, 1.0 - d);
          if (d > kLensViewTolerance && at_wrap(f_cpu, kLensViewTolerance) && at_wrap(f_gpu, kLensViewTolerance))
            ++p.wraps;
          else
            p.max_deviation = std::max(p.max_deviation, d);
          ++p.subpixels;
          if (display::LensModel::view_index(f_gpu, views) == display::LensModel::view_index(f_cpu, views)) continue;
          ++p.view_differs;
          const double a = lens.phase(lens.subpixel_uv(x, row, c));
          const double t = (a - std::floor(a)) * views;
          if (std::abs(t - std::round(t)) > kLensViewTolerance * views) ++p.view_differs_not_tie;
        }
  }
  return p;
}

std::vector<std::filesystem::path> calibrations() {
  std::vector<std::filesystem::path> files = test::fixture_calibrations();
  for (const char* name : {"32in-gen2", "32in-landscape-gen3", "32in-portrait-gen3", "16in-landscape-gen3", "go"})
    files.push_back(test::project_data() / "displays" / (std::string(name) + ".visual.json"));
  return files;
}

class LensViewOnWholePanels : public testing::TestWithParam<std::filesystem::path> {};

TEST_P(LensViewOnWholePanels, SinglePrecisionStaysWithinTheToleranceOfTheDoubleLensModel) {
  HeadlessContext context;
  const display::DisplayCalibration cal = display::read_visual_json(GetParam());
  const display::LensModel lens(cal);
  display::Calibration with_views;
  with_views.display = cal;
  const int views = display::quilt_for_display(with_views).views;
  const Precision p = measure(lens, views);
  std::printf("  %-28s %5dx%-5d max |f_GL - f_CPU| %.2e period, %zu wrap clamps, %zu of %zu subpixels show "
              "another of %d views (%zu not boundary ties)\n",
              GetParam().stem().stem().c_str(), cal.screen_w, cal.screen_h, p.max_deviation, p.wraps,
              p.view_differs, p.subpixels, views, p.view_differs_not_tie);
  EXPECT_LE(p.max_deviation, kLensViewTolerance);
  EXPECT_EQ(p.view_differs_not_tie, 0u);
  // Ties are rare: about 2 V kLensViewTolerance of the subpixels at most.
  EXPECT_LE(double(p.view_differs), 2.0 * views * kLensViewTolerance * double(p.subpixels) + 10.0);
}

INSTANTIATE_TEST_SUITE_P(RealCalibrationsUpTo8K, LensViewOnWholePanels, testing::ValuesIn(calibrations()),
                         [](const testing::TestParamInfo<std::filesystem::path>& info) {
                           std::string name = info.param.stem().stem().string();
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace lfd::gpu
