#pragma once
// The coarse patterns of a panel nobody described (docs/calibration.md, "A panel nobody
// described"): phase-stepped gratings ("probes") drawn without any lens description. Probe j
// shows on every subpixel
//     0.5 + 0.5 cos(2 pi (Fu u + Fv v - k / K)),   k = 0 .. K-1,
// with (u, v) the subpixel's screen coordinates in RGB stripes (display/lens_model.hpp). Drawn
// per subpixel, not per pixel: a lens of 1.5 pixels needs a grating finer than the pixels, and
// a grating sampled per pixel could not tell P' from W - P'. On a BGR panel red and blue sit
// a subpixel off, which leaves weaker images of the grating a pixel lattice away, not read.
// Each lens shows the camera one sample of it, so a photo shows the moire between the grating and the lens array: the phasor
// sum_k I_k exp(2 pi i k / K) is a plane wave of gradient (Fu, Fv) - m (P', P' tilt) (P' lens
// periods per screen width, m the nearest whole multiple), which a camera resolves when it is
// a few hundred cycles per screen or less. A bank of gratings whose windows tile the range of
// pitches (lenticules per inch) and slants asked for finds the lens; three steps or more give
// the moire's sign, hence the slant's (calib/lens_probes.hpp measures it).
#include <string>
#include <vector>

namespace lfd::sim {

struct LensProbe {
  double fu = 0;  // grating cycles per screen width (along u)
  double fv = 0;  // grating cycles per screen height (along v, up)
  // The moire this probe is read over: |moire u| <= window_u, |moire v| <= window_v (cycles
  // per screen width and height).
  double window_u = 0, window_v = 0;
};

struct ProbeOptions {
  double min_lpi = 10, max_lpi = 150;  // lenticules per inch, across the lens lines
  double max_slant_deg = 30;           // either sign
  // Camera pixels the screen will span in the photos (width; the height in proportion): how
  // fine a moire the photos resolve. The photographing guide asks for 50-70 % of a frame of
  // 1280 px or more.
  double camera_px_across = 700;
  // A moire is read up to this many cycles per camera pixel (blur and the camera's pixel
  // make finer ones too faint), and up to this fraction of the grating's own frequency (the
  // nearest multiple m of the lens must be 1, not 0).
  double cycles_per_camera_px = 0.3;
  double window_of_grating = 0.3;
  double overlap = 0.8;  // neighbouring windows overlap by 1 - this of their width
  int steps = 3;         // K >= 3: the moire's sign needs three
};

// The probes for a screen_w x screen_h panel at `dpi`: their windows cover every lens of
// pitch min_lpi..max_lpi and slant -max_slant_deg..max_slant_deg. Throws InputError for
// options that cannot work (names the field).
std::vector<LensProbe> plan_lens_probes(int screen_w, int screen_h, double dpi,
                                        const ProbeOptions& options = {});

}  // namespace lfd::sim
