#pragma once
// One frame of the viewer, all on the GPU: scene -> quilt (G2LF or per view) -> panel
// (interlacing shader), with no CPU round trip. The same class renders in the display window
// and in a headless context, which is how the viewer's test checks the window against the
// headless render of the same camera and settings.
#include <memory>
#include <optional>

#include "calib/display/calibration_file.hpp"
#include "calib/display/display_quilt.hpp"
#include "calib/display/lens_model.hpp"
#include "gpu/gl_context.hpp"
#include "gpu/gl_g2lf.hpp"
#include "gpu/gl_interlacer.hpp"
#include "gpu/gl_objects.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_scene.hpp"
#include "render/camera_json.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "viewer/control_window.hpp"
#include "viewer/viewer_settings.hpp"

namespace lfd::viewer {

// The quilt one frame renders for a display, camera and settings (pure; no GL).
struct FramePlan {
  calib::DisplayQuilt display_quilt;
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
};
FramePlan plan_frame(const calib::Calibration& calibration, const render::CameraSpec& camera,
                     const ViewerSettings& settings);

class LightFieldFrame {
 public:
  // Needs a current GL 4.5 context (`info` describes it). Uploads the scene once.
  LightFieldFrame(const render::GaussianScene& scene, const calib::Calibration& calibration,
                  const gpu::GlInfo& info);
  ~LightFieldFrame();

  // Renders the quilt and the panel for `camera` with `settings`; fills `report`'s GPU stage
  // times when `timers` (which waits for the GPU: fine once a frame in the viewer).
  void render(const render::CameraSpec& camera, const ViewerSettings& settings, FrameReport* report = nullptr);
  void replace_scene(const render::GaussianScene& scene);

  const gpu::Texture& quilt() const { return quilt_; }
  const gpu::Texture& panel() const { return panel_; }
  const render::QuiltLayout& layout() const { return plan_.layout; }
  const FramePlan& plan() const { return plan_; }

 private:
  calib::Calibration calibration_;
  calib::LensModel lens_;
  gpu::GlInfo info_;
  std::unique_ptr<gpu::GlScene> scene_;
  std::unique_ptr<gpu::GlPerViewRenderer> per_view_;
  std::unique_ptr<gpu::GlG2lfRenderer> g2lf_;
  std::unique_ptr<gpu::GlInterlacer> interlacer_;
  std::optional<render::QuiltLayout> interlacer_layout_;
  FramePlan plan_;
  gpu::Texture quilt_, panel_;
  gpu::GpuTimer interlace_timer_;
};

}  // namespace lfd::viewer
