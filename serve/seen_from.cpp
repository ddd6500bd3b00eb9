// The console's "Seen from" (docs/console.md).
#include "serve/seen_from.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "display/seen_from_preview.hpp"
#include "display/view_count.hpp"
#include "util/error.hpp"
#include "util/png_codec.hpp"

namespace lfd::serve {

namespace {

// Clears the one-at-a-time flag however the rendering ends.
struct RenderingTurn {
  std::atomic<bool>& flag;
  ~RenderingTurn() { flag = false; }
};

}  // namespace

SeenFromRenderer::SeenFromRenderer(DisplayService& displays, MemoryBudget& budget)
    : displays_(displays), budget_(budget) {}

ServedDisplay SeenFromRenderer::served(int display) const {
  const auto all = displays_.displays();
  if (display < 0 || display >= static_cast<int>(all.size()))
    throw_input_error("display: {} is not served (0..{})", display, static_cast<int>(all.size()) - 1);
  return all[static_cast<std::size_t>(display)];
}

SeenFromRange SeenFromRenderer::range(int display) const {
  const ServedDisplay d = served(display);
  const display::LensModel lens(d.calibration.display, d.calibration.correction);
  const int views = std::max(1, d.default_quilt.views);
  return {d.calibration.display.view_cone_deg, views, display::seen_from_view_angle_deg(lens, 0, views),
          display::seen_from_view_angle_deg(lens, views - 1, views), display::kDefaultSeenFromDistanceM,
          d.calibration.display.width_m(), d.calibration.display.height_m()};
}

double SeenFromRenderer::angle_of_view(int display, double view) const {
  const ServedDisplay d = served(display);
  const int views = std::max(1, d.default_quilt.views);
  if (!(view >= 0 && view <= views - 1)) throw_input_error("view: {} (expected 0 to {})", view, views - 1);
  return display::seen_from_view_angle_deg(display::LensModel(d.calibration.display, d.calibration.correction), view,
                                           views);
}

std::string SeenFromRenderer::png(int display, double angle_deg, int height_px) {
  const ServedDisplay d = served(display);
  if (!std::isfinite(angle_deg) || std::abs(angle_deg) > kSeenFromMaxAngleDeg)
    throw_input_error("angle: {} degrees (expected -{} to {})", angle_deg, kSeenFromMaxAngleDeg, kSeenFromMaxAngleDeg);
  if (height_px < kSeenFromMinHeightPx || height_px > kSeenFromMaxHeightPx)
    throw_input_error("height: {} px (expected {} to {})", height_px, kSeenFromMinHeightPx, kSeenFromMaxHeightPx);
  if (rendering_.exchange(true)) throw BusyError("seen from: another picture is being rendered; try again");
  const RenderingTurn turn{rendering_};

  // The read-back (8-bit RGB) and its float copy, which the optics read.
  const auto& c = d.calibration.display;
  const std::size_t panel_bytes = std::size_t(c.screen_w) * std::size_t(c.screen_h) * 3 * (1 + sizeof(float));
  const MemoryBudget::Reservation held = budget_.reserve_or_busy(panel_bytes, "the seen-from panel");
  const auto panel = displays_.panel_picture(display, kSeenFromPanelWait);
  if (!panel) throw BusyError("seen from: the display gave no picture in time; try again");

  const display::LensModel lens(c, d.calibration.correction);
  display::SeenFromOptions options;
  options.height_px = height_px;
  // Denser than the viewer's live preview (2 across): a picture asked now and then, whose mean
  // over a patch must not alias with the lenses (a lens shows a channel fully or not at all).
  options.pixels_across = kSeenFromPixelsAcross;
  options.psf_sigma_phase = d.calibration.phase_blur_sigma.value_or(display::kDefaultPhaseBlurSigma);
  display::SeenFromEye eye;
  eye.angle_deg = angle_deg;
  return png::encode_to_bytes("seen from", to_uint8(display::seen_from_preview(lens, to_float(*panel), eye, options)));
}

}  // namespace lfd::serve
