#pragma once
// What a quilt for one display looks like, chosen from its calibration (docs/display-model.md "The
// quilt for a display"): the view cone (the measured one when the calibration has it), the number
// of views (the calibration's recommendation unless the user asks for another), the tile grid and
// the aspect of one view (the panel's). `lfd render`, `lfd interlace` and the viewer ask this one
// place.
#include <optional>
#include <string>

#include "display/calibration_file.hpp"
#include "util/default_display.hpp"

namespace lfd::display {

struct QuiltGrid {
  int cols = 5;
  int rows = 9;
};

// The tile grid for `views` views whose tiles have width/height `view_aspect`: the fewest empty
// tiles, then the quilt texture closest to square (Looking Glass software's 5x9 for 45
// landscape views, 8x6 for 48 portrait ones). Throws InputError unless 1 <= views <= 256.
QuiltGrid quilt_grid_for_views(int views, double view_aspect);

// The view cone a renderer must use: the measured one when the calibration has it.
double effective_view_cone_deg(const Calibration& calibration);

struct DisplayQuilt {
  int views = kDefaultViewCount;
  QuiltGrid grid;
  double view_aspect = 1.0;  // screenW / screenH
  double view_cone_deg = kDefaultViewConeDeg;
  bool cone_measured = false;
  std::string views_source;  // "--views", "recommended by the calibration", "view-count rule"
  // One line for the user: what was chosen and why.
  std::string describe() const;
};

// The quilt for a display. `views` (the user's --views) overrides the calibration's
// recommendation; without either the view-count rule decides.
DisplayQuilt quilt_for_display(const Calibration& calibration, std::optional<int> views = {});

// The size of one view: `height_px` tall (default 512) at the display's aspect.
struct ViewSize {
  int width = 512, height = 512;
};
ViewSize view_size_for_display(const DisplayQuilt& quilt, int height_px = 512);

}  // namespace lfd::display
