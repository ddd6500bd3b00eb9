#include "viewer/light_field_frame.hpp"

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "display/display_quilt.hpp"
#include "render/per_view_quilt.hpp"
#include "util/error.hpp"

namespace lfd::viewer {
namespace {

double mib(double bytes) { return bytes / 1048576.0; }

double scene_gpu_bytes(size_t gaussians, int sh_degree) {
  return double(gaussians) * double(gpu::scene_bytes_per_gaussian(sh_degree) + gpu::per_view_scratch_bytes_per_gaussian());
}

std::string limit_text(const gpu::GlInfo& info) {
  std::string text;
  if (info.free_memory_bytes) text += fmt::format("; {:.0f} MiB free", mib(double(*info.free_memory_bytes)));
  if (info.max_ssbo_bytes > 0) text += fmt::format("; buffers of at most {:.0f} MiB", mib(double(info.max_ssbo_bytes)));
  return text;
}

}  // namespace

FramePlan plan_frame(const display::Calibration& calibration, const render::CameraSpec& camera,
                     const ViewerSettings& s) {
  FramePlan plan;
  plan.display_quilt = display::quilt_for_display(
      calibration, s.views > 0 ? std::optional<int>(s.views) : std::nullopt);
  const display::ViewSize size = display::view_size_for_display(plan.display_quilt, s.view_height_px);
  const render::Camera base = render::camera_from_spec(camera, size.width, size.height);
  const float distance = glm::length(camera.look_at - camera.position);
  const double cone = (s.view_cone_deg > 0 ? s.view_cone_deg : plan.display_quilt.view_cone_deg) * s.depthiness;
  plan.geometry = render::make_quilt_geometry(base, s.focal_fraction * distance, float(cone),
                                              plan.display_quilt.views);
  plan.layout = render::make_quilt_layout(plan.geometry, plan.display_quilt.grid.cols,
                                          plan.display_quilt.grid.rows);
  return plan;
}

LightFieldFrame::LightFieldFrame(const display::Calibration& calibration, const gpu::GlInfo& info,
                                 FrameOptions options)
    : calibration_(calibration),
      lens_(calibration.display, calibration.correction),
      info_(info),
      options_(std::move(options)) {
  panel_ = gpu::Texture(GL_RGBA8, calibration.display.screen_w, calibration.display.screen_h);
}

LightFieldFrame::LightFieldFrame(const render::GaussianScene& scene, const display::Calibration& calibration,
                                 const gpu::GlInfo& info, FrameOptions options)
    : LightFieldFrame(calibration, info, std::move(options)) {
  replace_scene(scene);
}

LightFieldFrame::LightFieldFrame(const voxel::VoxelScene& scene, const display::Calibration& calibration,
                                 const gpu::GlInfo& info, FrameOptions options)
    : LightFieldFrame(calibration, info, std::move(options)) {
  replace_scene(scene);
}

LightFieldFrame::LightFieldFrame(const ViewerScene& scene, const display::Calibration& calibration,
                                 const gpu::GlInfo& info, FrameOptions options)
    : LightFieldFrame(calibration, info, std::move(options)) {
  replace_scene(scene);
}

LightFieldFrame::~LightFieldFrame() = default;

void LightFieldFrame::drop_renderers() {
  // Renderers hold their scene by reference: they go first.
  g2lf_.reset();
  per_view_.reset();
  v2lf_.reset();
  voxel_views_.reset();
}

void LightFieldFrame::replace_scene(const ViewerScene& scene) {
  if (scene.voxels())
    replace_scene(scene.voxel_scene());
  else
    replace_scene(scene.gaussians());
}

void LightFieldFrame::replace_scene(const voxel::VoxelScene& scene) {
  gpu::check_voxel_scene_fits(scene.size(), scene.sh_degree, info_);  // refuses: the old scene kept
  drop_renderers();
  scene_.reset();
  voxel_scene_.reset();  // the old buffers go before the new ones are allocated: a lower peak
  scene_fit_notice_.clear();
  voxel_scene_ = std::make_unique<gpu::GlVoxelScene>(scene, info_);
}

void LightFieldFrame::replace_scene(const render::GaussianScene& scene) {
  drop_renderers();
  gpu::GlSceneOptions o;
  o.max_sh_degree = gpu::fitting_sh_degree(scene.size(), scene.sh_degree, info_);  // refuses: old scene kept
  o.progress = options_.upload_progress;
  o.chunk_gaussians = kUploadPieceGaussians;
  scene_fit_notice_.clear();
  if (o.max_sh_degree < scene.sh_degree)
    scene_fit_notice_ = fmt::format(
        "scene of {} Gaussians shown at SH degree {} (its own: {}): {:.0f} MiB on the GPU instead of {:.0f} MiB{}",
        scene.size(), o.max_sh_degree, scene.sh_degree, mib(scene_gpu_bytes(scene.size(), o.max_sh_degree)),
        mib(scene_gpu_bytes(scene.size(), scene.sh_degree)), limit_text(info_));
  scene_.reset();  // the old buffers go before the new ones are allocated: a lower peak
  voxel_scene_.reset();
  scene_ = std::make_unique<gpu::GlScene>(scene, info_, o);
}

void LightFieldFrame::render_g2lf(const ViewerSettings& settings, const render::RasterSettings& raster,
                                  bool timed) {
  if (!g2lf_) g2lf_ = std::make_unique<gpu::GlG2lfRenderer>(*scene_, info_);
  gpu::GlG2lfOptions o;
  o.g2lf = settings.g2lf;
  o.gpu_timers = timed;
  o.memory_budget_bytes = options_.g2lf_memory_budget_bytes;
  o.accumulation_budget_bytes = options_.g2lf_accumulation_budget_bytes;
  plane_fit_notice_.clear();
  try {
    g2lf_->render_quilt(plan_.geometry, plan_.layout, o, raster, quilt_);
  } catch (const InputError& refused) {
    // The memory check runs before anything is allocated or drawn: RGBA8 planes (a quarter of
    // the bytes, plus a bounded float accumulation array) may fit where RGBA32F ones do not.
    if (o.g2lf.precision == render::PlanePrecision::kU8) throw;
    o.g2lf.precision = render::PlanePrecision::kU8;
    try {
      g2lf_->render_quilt(plan_.geometry, plan_.layout, o, raster, quilt_);
    } catch (const InputError&) {
      throw refused;
    }
    plane_fit_notice_ = fmt::format("RGBA32F planes do not fit, so RGBA8 planes are shown ({})", refused.what());
  }
}

void LightFieldFrame::render_voxels(const ViewerSettings& settings, FrameReport* report) {
  if (report) {
    report->binning_seconds = report->planes_seconds = report->swizzle_seconds = report->raster_seconds = 0.0;
  }
  if (settings.method == Method::kG2lf) {
    if (!v2lf_) v2lf_ = std::make_unique<gpu::GlV2lfRenderer>(*voxel_scene_, info_);
    gpu::GlV2lfOptions o;
    o.v2lf.planes = settings.g2lf;
    o.v2lf.split_levels = 0;  // a split re-uploads the scene every frame
    v2lf_->render_quilt(plan_.geometry, plan_.layout, o, settings.background, quilt_);
  } else {
    if (!voxel_views_) voxel_views_ = std::make_unique<gpu::GlVoxelViews>(*voxel_scene_);
    voxel::VoxelRenderSettings s;
    s.background = settings.background;
    voxel_views_->render_quilt(plan_.geometry, plan_.layout, s, quilt_);
  }
}

void LightFieldFrame::render(const render::CameraSpec& camera, const ViewerSettings& settings,
                             FrameReport* report) {
  plan_ = plan_frame(calibration_, camera, settings);
  const render::QuiltLayout& layout = plan_.layout;
  if (quilt_.width() != layout.width || quilt_.height() != layout.height)
    quilt_ = gpu::Texture(GL_RGBA8, layout.width, layout.height);
  if (!interlacer_layout_ || interlacer_layout_->width != layout.width ||
      interlacer_layout_->height != layout.height || interlacer_layout_->cols != layout.cols ||
      interlacer_layout_->rows != layout.rows || interlacer_layout_->views != layout.views ||
      interlacer_layout_->aspect != layout.aspect) {
    interlacer_ = std::make_unique<gpu::GlInterlacer>(lens_, layout);
    interlacer_layout_ = layout;
  }
  render::RasterSettings raster;
  raster.background = settings.background;
  const bool timed = report != nullptr;
  if (voxel_scene_) {
    render_voxels(settings, report);
  } else if (settings.method == Method::kG2lf) {
    render_g2lf(settings, raster, timed);
  } else {
    if (!per_view_) {
      gpu::GlPerViewOptions o;
      o.gpu_timers = timed;
      per_view_ = std::make_unique<gpu::GlPerViewRenderer>(*scene_, o);
    }
    per_view_->render_quilt(plan_.geometry, layout, raster, quilt_);
  }
  if (timed) interlace_timer_.begin();
  interlacer_->interlace(quilt_, panel_);
  if (timed) interlace_timer_.end();

  if (!report) return;
  report->interlace_seconds = interlace_timer_.seconds();
  if (voxel_scene_) {
    // Stage times of the voxel path are not timed per stage; the frame time says it all.
    report->plane_bytes = v2lf_ && settings.method == Method::kG2lf ? v2lf_->stats().plane_bytes : 0;
  } else if (settings.method == Method::kG2lf) {
    const auto& st = g2lf_->stats();
    report->binning_seconds = st.seconds_binning;
    report->planes_seconds = st.seconds_planes;
    report->swizzle_seconds = st.seconds_swizzle;
    report->plane_bytes = st.plane_bytes;
  } else {
    const auto& st = per_view_->stats();
    report->raster_seconds = st.preprocess_s + st.sort_s + st.raster_s;
    report->plane_bytes = 0;
  }
  report->gpu_peak_bytes = gpu::gpu_bytes_peak();
  report->views = layout.views;
  report->cols = layout.cols;
  report->rows = layout.rows;
  report->view_width = plan_.geometry.base.width;
  report->view_height = plan_.geometry.base.height;
  report->view_cone_deg = glm::degrees(plan_.geometry.view_cone_rad);
}

}  // namespace lfd::viewer
