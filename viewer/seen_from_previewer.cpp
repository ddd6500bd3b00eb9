#include "viewer/seen_from_previewer.hpp"

#include <fmt/format.h>

#include "display/view_count.hpp"
#include "gpu/panel/gl_interlacer.hpp"

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
  if (readback_.busy()) {
    if (std::optional<Image8> panel = readback_.poll()) start_optics(std::move(*panel), frame.lens());
    return;
  }
  // The frame is a function of the camera and the settings; the preview also of the eye.
  const std::string key = fmt::format("{}|{}|{}|{}|{}", render::camera_json_text(camera), settings_to_json(settings),
                                      controls.eye.angle_deg, controls.eye.distance_m, controls.eye.height_m);
  if (!seen_from_refresh_due(controls.visible, key != shown_key_, age_seconds())) return;
  started_at_ = std::chrono::steady_clock::now();
  shown_key_ = key;
  readback_eye_ = controls.eye;
  readback_.start(frame.panel());  // GL (this thread), polled on the next frames
}

void SeenFromPreviewer::start_optics(Image8 panel, const display::LensModel& lens) {
  // The optics only read the panel, the lens and the eye.
  job_ = std::async(std::launch::async, [panel = std::move(panel), &lens, eye = readback_eye_, options = options_] {
    ImageF texels(panel.width, panel.height, panel.channels);
    for (size_t i = 0; i < panel.pixels.size(); ++i) texels.pixels[i] = float(panel.pixels[i]) / 255.0f;
    return seen_from_preview(lens, texels, eye, options);
  });
}

}  // namespace lfd::viewer
