#pragma once
// The console's "Seen from" (docs/console.md): the picture a served display shows now, as an eye
// at an angle within its view cone sees it, rendered on the service's CPU by the optics `lfd
// simulate` uses (display/seen_from_preview.hpp over display::LensOptics) for that unit's
// calibration. Bounded: one rendering at a time (another is busy at once, not queued), the
// panel's read-back and its float copy reserved from the service's memory budget, the picture
// at most kSeenFromMaxHeightPx rows, the display's read-back awaited at most kSeenFromPanelWait.
#include <atomic>
#include <chrono>
#include <string>

#include "serve/display_service.hpp"
#include "serve/memory_budget.hpp"

namespace lfd::serve {

inline constexpr int kSeenFromMinHeightPx = 16;
inline constexpr int kSeenFromMaxHeightPx = 512;
inline constexpr int kSeenFromDefaultHeightPx = 256;
inline constexpr double kSeenFromMaxAngleDeg = 80;  // the eye stays in front of the panel
inline constexpr std::chrono::milliseconds kSeenFromPanelWait{3000};
inline constexpr int kSeenFromPixelsAcross = 8;  // panel columns sampled per picture pixel

// The slider's span for a display: from the middle of its first view to the middle of its last
// (views: its default quilt's), an eye level with the panel centre at `distance_m`.
struct SeenFromRange {
  double cone_deg = 0;
  int views = 0;
  double first_view_deg = 0;
  double last_view_deg = 0;
  double distance_m = 0;
  double panel_width_m = 0, panel_height_m = 0;
};

class SeenFromRenderer {
 public:
  // Both outlive this object.
  SeenFromRenderer(DisplayService& displays, MemoryBudget& budget);

  // InputError for a display not served.
  SeenFromRange range(int display) const;
  // The angle (degrees) from which display `display` shows the middle of view `view` of its
  // default quilt's (fractions between two). InputError outside [0, views - 1].
  double angle_of_view(int display, double view) const;
  // The picture as PNG bytes (RGB, the panel's aspect, `height_px` rows). InputError for a
  // display not served, an angle outside +-kSeenFromMaxAngleDeg or not a number, a height
  // outside [kSeenFromMinHeightPx, kSeenFromMaxHeightPx]; BusyError while another rendering
  // runs, when the budget cannot hold the panel now, or when the display gave no picture in
  // time.
  std::string png(int display, double angle_deg, int height_px);

 private:
  ServedDisplay served(int display) const;

  DisplayService& displays_;
  MemoryBudget& budget_;
  std::atomic<bool> rendering_{false};
};

}  // namespace lfd::serve
