#pragma once
// The display half of the forward model (docs/validation.md "The forward model"): which panel light
// a lens sends from panel point P toward a viewing direction. Shared by
// DisplaySimulator::radiance() and ::capture(), so a photograph and a validation profile see the
// same optics.
#include <array>

#include "display/lens_model.hpp"
#include "display/lens_relations.hpp"
#include "display/phase_kernel.hpp"
#include "util/image.hpp"

namespace lfd::display {

class LensOptics {
 public:
  // `panel` must be screenW x screenH with 1, 3 or 4 channels (checked by the caller); lens,
  // panel and kernel must outlive this object. The kernel comes from make_kernel().
  LensOptics(const LensModel& lens, const ImageF& panel, const PhaseKernel& kernel);

  // The subpixel box blurred by the lens point spread sigma_A (lens periods) of this lens.
  static PhaseKernel make_kernel(const LensModel& lens, double psf_sigma_phase);

  // Linear radiance per channel (uniform white panel -> 1 on average over a lens) leaving
  // screen point (u, v) toward a viewer in direction tan_x = dx/dz, tan_y = dy/dz (display
  // frame, y up): the vertical direction counts through the slant of the lens lines.
  std::array<float, 3> seen(double u, double v, double tan_x, double tan_y) const;
  // The same toward a viewer at offset (dx, dy, dz) metres from the lens point (dz from the
  // lens plane): through the calibration's cover the light arrives from the refracted
  // direction (dx, dy) / cover_seen_distance(). Nothing for an eye at or inside the cover.
  std::array<float, 3> seen_toward(double u, double v, double dx, double dy, double dz) const;

  // The view fraction a lens sends toward (tan_x, tan_y), wrapped into [0, 1): outside the
  // cone the neighbouring lens repeats the views.
  double seen_fraction(double tan_x, double tan_y) const;
  // The point Q on the same horizontal line as (u, v) whose phase shows fraction f through
  // the lens covering (u, v).
  double seen_u(double u, double v, double fraction) const;

 private:
  float channel_emission(double u_q, double v, int channel) const;

  const LensModel& lens_;
  const ImageF& panel_;
  const PhaseKernel& kernel_;
  CoverLayer cover_;
  double view_cone_deg_ = 0;
  double pitch_periods_ = 0;
  double line_tilt_ = 0;
  bool has_correction_ = false;
  bool has_cells_ = false;
  int width_ = 0, height_ = 0;
  std::array<double, 3> channel_offset_u_{};  // classic layout: emitter offset from pixel centre
};

// The panel must be exactly the calibration's screenW x screenH; throws InputError otherwise.
void check_panel_size(const LensModel& lens, const ImageF& panel);

}  // namespace lfd::display
