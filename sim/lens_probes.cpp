#include "sim/lens_probes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "util/error.hpp"

namespace lfd::sim {

namespace {

void check(const ProbeOptions& o, int screen_w, int screen_h, double dpi) {
  const std::string where = "lens probes";
  require_field(screen_w > 0 && screen_h > 0, where, "screen", "must be a positive size");
  require_field(std::isfinite(dpi) && dpi > 0, where, "dpi", "must be positive");
  require_field(o.min_lpi > 0 && o.max_lpi > o.min_lpi && o.max_lpi <= 1000, where, "lpi range",
                "must be 0 < min < max <= 1000 lenticules per inch");
  require_field(o.max_slant_deg >= 0 && o.max_slant_deg <= 60, where, "max_slant_deg",
                "must lie in 0..60 degrees");
  require_field(o.camera_px_across >= 100, where, "camera_px_across",
                "must be at least 100 camera pixels");
  require_field(o.cycles_per_camera_px > 0 && o.cycles_per_camera_px < 0.5, where,
                "cycles_per_camera_px", "must lie in (0, 0.5): the camera's Nyquist limit");
  require_field(o.window_of_grating > 0 && o.window_of_grating < 0.5, where,
                "window_of_grating", "must lie in (0, 0.5)");
  require_field(o.overlap > 0.3 && o.overlap <= 1, where, "overlap", "must lie in (0.3, 1]");
  require_field(o.steps >= 3 && o.steps <= 32, where, "steps",
                "must be 3..32 (the moire's sign needs three)");
}

}  // namespace

std::vector<LensProbe> plan_lens_probes(int screen_w, int screen_h, double dpi,
                                        const ProbeOptions& o) {
  check(o, screen_w, screen_h, dpi);
  const double width_in = screen_w / dpi;
  const double aspect = double(screen_h) / screen_w;
  const double max_tan = std::tan(o.max_slant_deg * std::numbers::pi / 180.0);
  // Lens periods per screen width: pitch (across the lines) x width x cos(slant).
  const double p_min = o.min_lpi * width_in * std::cos(o.max_slant_deg * std::numbers::pi / 180.0);
  const double p_max = o.max_lpi * width_in;
  const double camera_u = o.cycles_per_camera_px * o.camera_px_across;
  const double camera_v = camera_u * aspect;
  const double g = o.window_of_grating;
  // The grating whose window starts at `lower`: its window is the camera's or a fraction of
  // the grating, whichever is smaller.
  auto grating_from_lower = [&](double lower) {
    const double fu = lower / (1.0 - g);
    return g * fu <= camera_u ? fu : lower + camera_u;
  };
  std::vector<LensProbe> probes;
  double fu = grating_from_lower(0.98 * p_min);  // the range's ends inside, not on, an edge
  while (true) {
    const double wu = std::min(camera_u, g * fu);
    // The lens lines cross at most this many periods over the height (P' tilt, tilt =
    // (H / W) tan(slant)) for the pitches this grating's window holds.
    const double v_max = (fu + wu) * aspect * max_tan;
    const double wv = camera_v;
    const int n = v_max <= wv ? 0 : int(std::ceil((v_max - wv) / (2.0 * o.overlap * wv)));
    for (int i = -n; i <= n; ++i) probes.push_back({fu, i * 2.0 * o.overlap * wv, wu, wv});
    if (fu + wu >= p_max) break;
    fu = grating_from_lower(fu + o.overlap * wu);
  }
  return probes;
}

}  // namespace lfd::sim
