#pragma once
// The control window's "seen from" preview (docs/viewer.md): the picture itself is
// display::seen_from_preview (display/seen_from_preview.hpp, shared with `lfd serve`'s console);
// here only when the viewer recomputes it.
#include "display/seen_from_preview.hpp"

namespace lfd::viewer {

using display::kDefaultSeenFromDistanceM;
using display::seen_from_preview;
using display::SeenFromEye;
using display::SeenFromOptions;

// The preview needs the panel on the CPU, a read-back of the whole panel texture (tens of MB
// on an 8K panel): only while the preview is shown, only when the frame or the eye changed
// since the last one, and at most every kSeenFromMinIntervalS. `seconds_since_last` < 0: none yet.
inline constexpr double kSeenFromMinIntervalS = 0.25;
inline bool seen_from_refresh_due(bool visible, bool changed, double seconds_since_last) {
  if (!visible) return false;
  if (seconds_since_last < 0) return true;
  return changed && seconds_since_last >= kSeenFromMinIntervalS;
}

}  // namespace lfd::viewer
