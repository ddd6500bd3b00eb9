#include "live/simulated_live_devices.hpp"

#include <utility>

#include "util/error.hpp"

namespace lfd::live {

SimulatedCamera::SimulatedCamera(const display::Calibration& truth, sim::CaptureRig rig,
                                 std::function<Image8()> screen)
    : simulator_(display::LensModel(truth.display, truth.correction)),
      rig_(std::move(rig)),
      screen_(std::move(screen)),
      exposure_(rig_.effects.exposure) {
  if (rig_.poses.empty()) throw_input_error("simulated camera: the rig has no poses");
}

sim::PhysicalCamera SimulatedCamera::camera() const {
  return sim::PhysicalCamera(rig_.intrinsics, rig_.poses[size_t(position_) % rig_.poses.size()]);
}

void SimulatedCamera::start_position(int index, int) {
  position_ = index;
  photo_ = 0;
}

void SimulatedCamera::fix_exposure_on_white() {
  ++locks_;
  exposure_ = sim::exposure_on_white(simulator_, to_float(screen_()), camera(), rig_.effects);
}

cv::Mat SimulatedCamera::preview() {
  sim::CaptureEffects e = sim::photo_effects(rig_, size_t(position_), size_t(photo_));
  e.exposure = exposure_;
  return sim::to_mat(simulator_.capture(to_float(screen_()), camera(), e));
}

cv::Mat SimulatedCamera::capture() {
  sim::CaptureEffects e = sim::photo_effects(rig_, size_t(position_), size_t(photo_++));
  e.exposure = exposure_;
  return sim::to_mat(simulator_.capture(to_float(screen_()), camera(), e));
}

}  // namespace lfd::live
