#pragma once
// The camera half of the forward model (docs/validation.md "The forward model"): what a real
// photograph adds to the light arriving at the sensor, in the order a camera applies it: exposure
// gain, defocus blur, vignetting, glare, exposure drift and flicker banding, sensor noise, response
// curve (gamma), clipping and 8-bit quantisation. Random effects draw from seeded generators, so a
// seed fixes the capture.
#include "sim/camera_model.hpp"
#include "sim/simulator.hpp"
#include "util/image.hpp"

namespace lfd::sim {

// Applies every effect in place to a linear 3-channel sensor image of the camera's size.
void apply_camera_effects(ImageF& image, const CameraIntrinsics& intrinsics,
                          const CaptureEffects& effects);

// Throws InputError naming the effect for values no camera can have (negative blur, noise,
// vignetting outside [0, 1), non-positive gamma or exposure, flicker amplitude outside
// 0..0.2 or bands <= 0, supersample outside 1-16).
void check_effects(const CaptureEffects& effects);

}  // namespace lfd::sim
