#pragma once
// The GL side of the "seen from" preview: reads the panel back from the GPU when
// seen_from_refresh_due says so, through a pixel buffer and a fence polled on later frames
// (gpu/gl/gl_async_readback.hpp: the frame loop never waits for the GPU), computes
// seen_from_preview on a worker thread (nor for the optics) and keeps the result as a texture
// for the control window.
#include <chrono>
#include <future>
#include <optional>
#include <string>

#include "display/calibration_file.hpp"
#include "gpu/gl/gl_async_readback.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "render/camera_json.hpp"
#include "viewer/control_window.hpp"
#include "viewer/light_field_frame.hpp"
#include "viewer/seen_from_preview.hpp"
#include "viewer/viewer_settings.hpp"

namespace lfd::viewer {

class SeenFromPreviewer {
 public:
  // The lens point spread is the calibration's, else the default, as `lfd simulate`'s.
  explicit SeenFromPreviewer(const display::Calibration& calibration);

  // Needs the display window's context current (the panel texture lives there). Picks up a
  // finished preview; starts the next one when due and none is under way.
  void update(const SeenFromControls& controls, const LightFieldFrame& frame, const render::CameraSpec& camera,
              const ViewerSettings& settings);

  const gpu::Texture* texture() const { return texture_.id() ? &texture_ : nullptr; }
  double age_seconds() const;  // < 0 before the first preview
  double last_compute_seconds() const { return compute_seconds_; }  // read-back + optics

 private:
  // The panel arrived: the optics start on a worker thread.
  void start_optics(Image8 panel, const display::LensModel& lens);

  SeenFromOptions options_;
  std::string shown_key_;  // what the texture shows: the frame and the eye
  std::optional<std::chrono::steady_clock::time_point> computed_at_;
  std::chrono::steady_clock::time_point started_at_;
  gpu::AsyncTextureReadback readback_;  // the panel on its way to the CPU
  SeenFromEye readback_eye_;            // the eye the panel under way is for
  std::future<ImageF> job_;  // its destructor waits: declare the previewer after the frame
  double compute_seconds_ = 0;
  gpu::Texture texture_;
};

}  // namespace lfd::viewer
