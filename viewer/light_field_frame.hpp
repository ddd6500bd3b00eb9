#pragma once
// One frame of the viewer, all on the GPU: scene -> quilt (G2LF or per view; for a voxel scene
// V2LF or per view: the library's GL renderers, lightfield/renderer_factory.hpp, on the current
// context) -> panel (interlacing shader), with no CPU round trip of the images. The same class renders in the display window
// and in a headless context, which is how the viewer's test checks the window against the
// headless render of the same camera and settings.
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "display/lens_model.hpp"
#include "gpu/gl/raster_path.hpp"
#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_frame_ring.hpp"
#include "gpu/splats/gl_g2lf.hpp"
#include "gpu/panel/gl_interlacer.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "lightfield/gl_device.hpp"
#include "lightfield/gl_renderer.hpp"
#include "lightfield/view_plan.hpp"
#include "render/camera_json.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "viewer/control_window.hpp"
#include "viewer/viewer_settings.hpp"

namespace lfd::viewer {

// The views one frame renders for a display, camera and settings: the settings as a request of
// the view plan (lightfield/view_plan.hpp; pure, no GL).
lightfield::ViewPlan plan_frame(const display::Calibration& calibration, const render::CameraSpec& camera,
                     const ViewerSettings& settings);

// The scene goes to the GPU in pieces of this many Gaussians (progress four times a million).
inline constexpr size_t kUploadPieceGaussians = size_t(1) << 18;
// Called between the pieces of a scene upload with (Gaussians uploaded, total).
using UploadProgress = std::function<void(size_t done, size_t total)>;

struct FrameOptions {
  UploadProgress upload_progress;  // may be empty
  // GPU bytes G2LF may allocate; 0: the free memory the driver reports (tests inject a budget).
  size_t g2lf_memory_budget_bytes = 0;
  // The float accumulation array of RGBA8 planes (gpu::GlG2lfOptions).
  size_t g2lf_accumulation_budget_bytes = gpu::GlG2lfOptions{}.accumulation_budget_bytes;
  // How Gaussians are drawn (`lfd view --raster`; auto: measured once per run, docs/gpu.md).
  gpu::RasterPath raster = gpu::RasterPath::kHardware;
};

class LightFieldFrame {
 public:
  // Needs a current GL 4.5 context (`info` describes it, its limits included). Uploads the scene
  // once, at the largest SH degree that fits (gpu::fitting_sh_degree).
  LightFieldFrame(const scene::GaussianScene& scene, const display::Calibration& calibration,
                  const gpu::GlInfo& info, FrameOptions options = {});
  // A voxel scene: the settings' G2LF method renders it with V2LF (the same plane options, no
  // voxel splitting: interactive frames), per view with the exact voxel raster.
  LightFieldFrame(const scene::VoxelScene& scene, const display::Calibration& calibration,
                  const gpu::GlInfo& info, FrameOptions options = {});
  LightFieldFrame(const scene::Scene& scene, const display::Calibration& calibration, const gpu::GlInfo& info,
                  FrameOptions options = {});
  ~LightFieldFrame();

  // Renders the quilt and the panel for `camera` with `settings`; fills `report`'s GPU stage
  // times when given: those of the newest frame the GPU has finished, read without waiting
  // (gpu/gl/gl_frame_ring.hpp; a few frames late).
  // RGBA32F planes that do not fit fall back to RGBA8 when those fit (fit_notice() says so).
  void render(const render::CameraSpec& camera, const ViewerSettings& settings, FrameReport* report = nullptr);
  void replace_scene(const scene::GaussianScene& scene);
  void replace_scene(const scene::VoxelScene& scene);
  void replace_scene(const scene::Scene& scene);
  bool shows_voxels() const { return device_->voxels() != nullptr; }

  // The SH degree the scene was uploaded at, and what was lowered to fit (empty: nothing).
  int scene_sh_degree() const;
  const std::string& scene_fit_notice() const { return scene_fit_notice_; }
  const std::string& plane_fit_notice() const { return plane_fit_notice_; }
  // Why the raster path changed (the compute path failed on this device); empty: it did not.
  const std::string& raster_notice() const { return raster_notice_; }
  const display::LensModel& lens() const { return lens_; }
  const display::Calibration& calibration() const { return calibration_; }

  const gpu::Texture& quilt() const { return quilt_; }
  const gpu::Texture& panel() const { return panel_; }
  const render::QuiltLayout& layout() const { return plan_.layout; }
  const lightfield::ViewPlan& plan() const { return plan_; }

 private:
  // The members every scene kind shares (the lens, the panel); the public constructors add the scene.
  LightFieldFrame(const display::Calibration& calibration, const gpu::GlInfo& info, FrameOptions options);
  // The quilt of `settings`' method into quilt_; its figures. A compute path that fails on the
  // device is left for the hardware one (raster_notice()).
  lightfield::QuiltStats render_quilt(const ViewerSettings& settings, bool timed);
  lightfield::QuiltStats render_quilt_by(gpu::RasterPath raster, const ViewerSettings& settings, bool timed);
  // G2LF, falling back from RGBA32F to RGBA8 planes when those do not fit.
  lightfield::QuiltStats render_g2lf(lightfield::GlLightFieldRenderer& renderer, lightfield::RendererOptions options);
  void fill_report(const ViewerSettings& settings, const lightfield::QuiltStats& stats, FrameReport& report);
  void drop_renderers();

  display::Calibration calibration_;
  display::LensModel lens_;
  gpu::GlInfo info_;
  FrameOptions options_;
  std::string scene_fit_notice_, plane_fit_notice_, raster_notice_;
  std::shared_ptr<lightfield::GlDevice> device_;  // the current context and the uploaded scene
  std::unique_ptr<lightfield::GlLightFieldRenderer> per_view_, sweeping_;  // made on first use
  std::unique_ptr<gpu::GlInterlacer> interlacer_;
  std::optional<render::QuiltLayout> interlacer_layout_;
  lightfield::ViewPlan plan_;
  gpu::Texture quilt_, panel_;
  gpu::GlFrameRing interlace_timer_{2, 0};  // the interlacing pass's start and end
};

}  // namespace lfd::viewer
