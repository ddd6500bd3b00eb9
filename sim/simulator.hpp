#pragma once
// The optics simulator: what a camera sees of a lenticular display showing a panel image
// (docs/validation.md "The forward model"). The display follows its TRUE calibration (lens model
// with correction field); the camera adds projection and lens distortion, defocus blur,
// exposure, vignetting, gamma, sensor noise and 8-bit quantisation. Camera pixels are
// supersampled over their footprint on the panel.
#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "sim/camera_model.hpp"
#include "display/lens_model.hpp"
#include "util/image.hpp"

namespace lfd::sim {

struct CaptureEffects {
  double psf_sigma_phase = 0.008;  // lens point spread (sigma_A), lens periods: the crosstalk
  double blur_px = 0.0;            // camera defocus, Gaussian sigma in camera pixels
  double noise_sigma = 0.0;        // sensor noise, fraction of full scale
  double vignetting = 0.0;         // relative fall-off at the image corner (cos^4-like)
  double gamma = 1.0;              // camera response: out = in^(1/gamma)
  double exposure = 1.0;           // gain before clipping
  // Exposure that drifts from photo to photo (webcam auto exposure, backlight flicker): each
  // photo's gain is exposure * (1 + exposure_drift * N(0, 1)), drawn from its seed.
  double exposure_drift = 0.0;
  // Flicker seen through a rolling shutter (100/120 Hz room light, all the light alike): the
  // rows are exposed one after another, so the gain bands along them,
  // 1 + flicker_amplitude sin(2 pi (flicker_bands y / height + phi)), y the image row and phi
  // drawn from the photo's seed (the shutter does not follow the flicker).
  double flicker_amplitude = 0.0;  // relative, 0 to 0.2
  double flicker_bands = 2.5;      // bright bands over the image height, > 0
  double glare_fraction = 0.0;     // fraction of pixels replaced by saturated glare blobs
  // Camera colour crosstalk: each channel also records this fraction of each other channel's
  // light (overlapping Bayer filter passbands, demosaicking). It dilutes the per-channel phase
  // offsets that a wrong subpixel order leaves (calib/decoding/colour_order.hpp) by about 1 - 3x.
  double colour_crosstalk = 0.0;
  std::array<float, 3> bezel{0.03f, 0.03f, 0.035f};  // what is seen outside the panel
  int supersample = 3;             // samples per camera pixel per axis
  uint64_t seed = 1;               // noise (and glare, unless glare_seed is set)
  // Reflections of room lights stay where they are while the camera and the room do: the
  // photos of one camera position share one glare_seed (0: glare follows `seed`).
  uint64_t glare_seed = 0;
};

class DisplaySimulator {
 public:
  explicit DisplaySimulator(display::LensModel truth);
  const display::LensModel& lens() const { return lens_; }

  // Linear radiance (per channel, 1 = full white) leaving panel point `on_panel` (metres,
  // display frame, z = 0) toward `eye`, for a panel image of exactly screenW x screenH
  // (values in [0, 1], row 0 = top). No camera effects: this is what validation integrates.
  std::array<float, 3> radiance(const ImageF& panel, const Eigen::Vector3d& on_panel,
                                const Eigen::Vector3d& eye, double psf_sigma_phase) const;

  // A full photograph with every capture effect, as 8-bit-quantised floats in [0, 1].
  // Throws InputError if the panel is not screenW x screenH.
  ImageF capture(const ImageF& panel, const PhysicalCamera& camera,
                 const CaptureEffects& effects) const;

 private:
  display::LensModel lens_;
};

}  // namespace lfd::sim
