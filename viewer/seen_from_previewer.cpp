#include "viewer/seen_from_previewer.hpp"

#include <fmt/format.h>

#include "display/view_count.hpp"
#include "gpu/gl_interlacer.hpp"

namespace lfd::viewer {
namespace {

double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

SeenFromPreviewer::SeenFromPreviewer(const display::Calibration& calibration) {
  options_.psf_sigma_phase = calibration.phase_blur_sigma.value_or(display::kDefaultPhaseBlurSigma);
}

double SeenFromPreviewer::age_seconds() const {
  return computed_at_ ? seconds_between(*computed_at_, std::chrono::steady_clock::now()) : -1.0;
}

void SeenFromPreviewer::update(const SeenFromControls& controls, const LightFieldFrame& frame,
                               const render::CameraSpec& camera, const ViewerSettings& settings) {
  if (job_.valid()) {
    if (job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    texture_ = gpu::texture_from_image(job_.get());
    computed_at_ = std::chrono::steady_clock::now();
    compute_seconds_ = seconds_between(started_at_, *computed_at_);
  }
  // The frame is a function of the camera and the settings; the preview also of the eye.
  const std::string key = fmt::format("{}|{}|{}|{}|{}", render::camera_json_text(camera), settings_to_json(settings),
                                      controls.eye.angle_deg, controls.eye.distance_m, controls.eye.height_m);
  if (!seen_from_refresh_due(controls.visible, key != shown_key_, age_seconds())) return;
  started_at_ = std::chrono::steady_clock::now();
  shown_key_ = key;
  // The read-back is GL (this thread); the optics only read the panel, the lens and the eye.
  job_ = std::async(std::launch::async,
                    [panel = gpu::image_from_texture(frame.panel()), &lens = frame.lens(), eye = controls.eye,
                     options = options_] { return seen_from_preview(lens, panel, eye, options); });
}

}  // namespace lfd::viewer
