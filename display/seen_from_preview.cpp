#include "display/seen_from_preview.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "display/lens_optics.hpp"
#include "display/lens_relations.hpp"
#include "util/error.hpp"

namespace lfd::display {
namespace {

// A point or an eye in the display frame (metres).
struct Point3 {
  double x = 0, y = 0, z = 0;
};

// The one call into the optics: the light leaving panel point `on_panel` toward `eye`. The
// lens has power across its lines only, so the direction across the slanted lines (horizontal
// plus line_tilt times vertical) decides which view is seen.
std::array<float, 3> light_toward_eye(const LensOptics& optics, double u, double v, const Point3& on_panel,
                                      const Point3& eye) {
  // Both directions: a slanted lens shows an eye above or below the point another view; and
  // through the display's cover layer the refracted one.
  return optics.seen_toward(u, v, eye.x - on_panel.x, eye.y - on_panel.y, eye.z - on_panel.z);
}

// For each of `cells` preview cells over `pixels` panel pixels: at most `most` panel pixels of
// the cell's footprint, evenly spread (at least the one under its centre).
std::vector<std::vector<int>> footprint_cells(int cells, int pixels, int most) {
  std::vector<std::vector<int>> out(static_cast<size_t>(cells));
  for (int i = 0; i < cells; ++i) {
    const double begin = double(i) * pixels / cells, end = double(i + 1) * pixels / cells;
    const int first = int(std::ceil(begin - 0.5)), last = int(std::ceil(end - 0.5)) - 1;  // centres inside
    const int inside = last - first + 1;
    if (inside < 1) {
      out[i].push_back(std::clamp(int(0.5 * (begin + end)), 0, pixels - 1));
      continue;
    }
    const int n = std::min(inside, most);
    for (int k = 0; k < n; ++k) out[i].push_back(first + int((k + 0.5) * inside / n));
  }
  return out;
}

}  // namespace

void SeenFromOptions::check() const {
  if (height_px < 2 || height_px > 4096) throw_input_error("seen-from preview: height: {} px (expected 2 to 4096)", height_px);
  if (pixels_across < 1 || pixels_across > 64)
    throw_input_error("seen-from preview: pixels across: {} (expected 1 to 64)", pixels_across);
  if (rows_down < 1 || rows_down > 64) throw_input_error("seen-from preview: rows down: {} (expected 1 to 64)", rows_down);
  if (!(psf_sigma_phase >= 0 && psf_sigma_phase < 1))
    throw_input_error("seen-from preview: psf: {} lens periods (expected 0 <= psf < 1)", psf_sigma_phase);
}

ImageF seen_from_preview(const LensModel& lens, const ImageF& panel, const SeenFromEye& eye,
                         const SeenFromOptions& options) {
  options.check();
  check_panel_size(lens, panel);
  if (!(eye.distance_m > 0)) throw_input_error("seen-from preview: distance: {} m (expected > 0)", eye.distance_m);
  const auto& c = lens.calibration();
  const double width_m = c.width_m(), height_m = c.height_m();
  const int h = options.height_px;
  const int w = std::max(1, int(std::lround(h * width_m / height_m)));
  const double angle = eye.angle_deg * std::numbers::pi / 180.0;
  const Point3 eye_m{eye.distance_m * std::sin(angle), eye.height_m, eye.distance_m * std::cos(angle)};
  const PhaseKernel kernel = LensOptics::make_kernel(lens, options.psf_sigma_phase);
  const LensOptics optics(lens, panel, kernel);

  // Toward one eye a whole lens shows one seen point Q (the phase that sends light there), and
  // each channel emits from a third of a pixel: a lens shows a channel fully or not at all, and
  // which depends on where Q falls, lens by lens and row by row (the slant moves Q along a
  // row). An eye resolves neither, so a preview pixel averages points over its footprint,
  // rows above all, as the simulator's supersampled camera pixels do.
  const std::vector<std::vector<int>> columns = footprint_cells(w, c.screen_w, options.pixels_across);
  const std::vector<std::vector<int>> rows = footprint_cells(h, c.screen_h, options.rows_down);
  ImageF out(w, h, 3);
#pragma omp parallel for schedule(dynamic, 4)
  for (int y = 0; y < h; ++y) {
    float* row = out.row(y);
    for (int x = 0; x < w; ++x) {
      std::array<double, 3> sum{0, 0, 0};
      for (int panel_row : rows[y])
        for (int panel_x : columns[x]) {
          // Screen coordinates as Looking Glass's: u right, v up (row 0 at the top).
          const double u = (panel_x + 0.5) / c.screen_w;
          const double v = 1.0 - (panel_row + 0.5) / c.screen_h;
          const Point3 on_panel{(u - 0.5) * width_m, (v - 0.5) * height_m, 0.0};
          const std::array<float, 3> light = light_toward_eye(optics, u, v, on_panel, eye_m);
          for (int ch = 0; ch < 3; ++ch) sum[ch] += light[ch];
        }
      const double inv_samples = 1.0 / double(rows[y].size() * columns[x].size());
      for (int ch = 0; ch < 3; ++ch) row[x * 3 + ch] = float(std::clamp(sum[ch] * inv_samples, 0.0, 1.0));
    }
  }
  return out;
}

double seen_from_view_angle_deg(const LensModel& lens, double view, int views) {
  if (views < 1 || !(view >= -0.5 && view <= views - 0.5))
    throw_input_error("seen from: view {} of {} (expected -0.5 to {}, within the cone)", view, views, views - 0.5);
  const double tan_theta = tan_of_seen_fraction((view + 0.5) / views, lens.calibration().view_cone_deg);
  return std::atan(tan_theta) * 180.0 / std::numbers::pi;
}

}  // namespace lfd::display
