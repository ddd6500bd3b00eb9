#include "viewer/light_field_frame.hpp"

#include <iostream>

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "display/display_quilt.hpp"
#include "gpu/gl/gl_fault.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "lightfield/renderer_factory.hpp"
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

lightfield::ViewPlan plan_frame(const display::Calibration& calibration, const render::CameraSpec& camera,
                                const ViewerSettings& s) {
  lightfield::ViewRequest request;
  request.display = &calibration;
  if (s.views > 0) request.views = s.views;
  if (s.view_cone_deg > 0) request.view_cone_deg = s.view_cone_deg;
  request.cone_scale = s.depthiness;
  // The display always sizes the viewer's views, whatever size a loaded cam.json names.
  request.camera = camera;
  request.camera->width.reset();
  request.camera->height.reset();
  request.view_height = s.view_height_px;
  request.focal_scale = s.focal_fraction;
  return lightfield::plan_views(request);
}

LightFieldFrame::LightFieldFrame(const display::Calibration& calibration, const gpu::GlInfo& info,
                                 FrameOptions options)
    : calibration_(calibration),
      lens_(calibration.display, calibration.correction),
      info_(info),
      options_(std::move(options)),
      device_(lightfield::GlDevice::on_current_context(info)) {
  panel_ = gpu::Texture(GL_RGBA8, calibration.display.screen_w, calibration.display.screen_h);
}

LightFieldFrame::LightFieldFrame(const scene::GaussianScene& scene, const display::Calibration& calibration,
                                 const gpu::GlInfo& info, FrameOptions options)
    : LightFieldFrame(calibration, info, std::move(options)) {
  replace_scene(scene);
}

LightFieldFrame::LightFieldFrame(const scene::VoxelScene& scene, const display::Calibration& calibration,
                                 const gpu::GlInfo& info, FrameOptions options)
    : LightFieldFrame(calibration, info, std::move(options)) {
  replace_scene(scene);
}

LightFieldFrame::LightFieldFrame(const scene::Scene& scene, const display::Calibration& calibration,
                                 const gpu::GlInfo& info, FrameOptions options)
    : LightFieldFrame(calibration, info, std::move(options)) {
  replace_scene(scene);
}

LightFieldFrame::~LightFieldFrame() = default;

int LightFieldFrame::scene_sh_degree() const {
  return device_->gaussians() ? device_->gaussians()->sh_degree() : device_->voxels()->scene().sh_degree;
}

void LightFieldFrame::drop_renderers() {
  // Renderers hold their scene: they go first.
  sweeping_.reset();
  per_view_.reset();
}

void LightFieldFrame::replace_scene(const scene::Scene& scene) {
  if (scene.kind() == scene::SceneKind::kVoxels)
    replace_scene(scene.voxels());
  else
    replace_scene(scene.gaussians());
}

void LightFieldFrame::replace_scene(const scene::VoxelScene& scene) {
  gpu::check_voxel_scene_fits(scene.size(), scene.sh_degree, info_);  // refuses: the old scene kept
  drop_renderers();
  scene_fit_notice_.clear();
  device_->upload(scene);  // the old buffers go before the new ones are allocated: a lower peak
}

void LightFieldFrame::replace_scene(const scene::GaussianScene& scene) {
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
  device_->upload(scene, o);  // the old buffers go before the new ones are allocated: a lower peak
}

lightfield::QuiltStats LightFieldFrame::render_g2lf(lightfield::GlLightFieldRenderer& renderer,
                                                    lightfield::RendererOptions options) {
  plane_fit_notice_.clear();
  try {
    return renderer.render_quilt_into(plan_.geometry, plan_.layout, quilt_);
  } catch (const InputError& refused) {
    // The memory check runs before anything is allocated or drawn: u8 planes (RGBA16F, half the
    // bytes, or RGBA8 with a bounded float accumulation array when those do not fit either;
    // docs/gpu.md "Planes") may fit where RGBA32F ones do not.
    if (options.planes.precision == render::PlanePrecision::kU8) throw;
    options.planes.precision = render::PlanePrecision::kU8;
    renderer.set_options(options);
    lightfield::QuiltStats stats;
    try {
      stats = renderer.render_quilt_into(plan_.geometry, plan_.layout, quilt_);
    } catch (const InputError&) {
      throw refused;
    }
    plane_fit_notice_ = fmt::format("RGBA32F planes do not fit, so u8 planes (RGBA16F, else RGBA8) are shown ({})", refused.what());
    return stats;
  }
}

lightfield::QuiltStats LightFieldFrame::render_quilt(const ViewerSettings& settings, bool timed) {
  try {
    return render_quilt_by(options_.raster, settings, timed);
  } catch (const gpu::GlPathFailed& failed) {
    // The compute path failed on this driver (docs/gpu.md "Drivers and limits"): the viewer
    // keeps running on the raster pipeline and says so once.
    if (options_.raster == gpu::RasterPath::kHardware) throw;
    options_.raster = gpu::RasterPath::kHardware;
    drop_renderers();
    raster_notice_ = fmt::format("the compute raster path failed ({}): drawing with the hardware path", failed.what());
    std::cerr << "notice: " << raster_notice_ << "\n";
    return render_quilt_by(options_.raster, settings, timed);
  }
}

lightfield::QuiltStats LightFieldFrame::render_quilt_by(gpu::RasterPath raster, const ViewerSettings& settings,
                                                        bool timed) {
  lightfield::RendererOptions o;
  o.backend = lightfield::Backend::kGl;
  const bool sweeping = settings.method != Method::kPerView;
  o.method = sweeping ? lightfield::Method::kSweepingPlanes : lightfield::Method::kPerView;
  o.planes = settings.g2lf;
  o.direct_filter = settings.g2lf.filter;  // the control window's one plane filter toggle
  o.split_levels = 0;  // V2LF: a split re-uploads the scene every frame
  o.background = settings.background;
  o.gl.gpu_timers = timed;
  o.gl.timer_reads = gpu::TimerReads::kLate;  // never wait for the GPU in a frame
  // Per view: 2 radix passes of 16-bit depth keys spread over the visible depth range instead
  // of 4 of the exact 32 bits (62 dB against the CPU on demo.ply, as the 24 float bits of 3
  // passes, instead of 84 dB, above an 8-bit panel's 48 dB; docs/gpu.md "Sorting what is
  // visible").
  o.gl.depth_key_bits = 16;
  o.gl.normalised_depth_keys = true;
  // Per view: blending into RGBA16F, half the bytes of RGBA32F: the per-view frame is fill-bound
  // on a GPU (an H200, 1M Gaussians, 45 views of 512x512: 1036 -> 406 ms, lfd bench gpu-frame);
  // 64 dB against the CPU on a generated scene (tests/gpu/gl_per_view_test.cpp).
  o.gl.per_view_accumulation_format = GL_RGBA16F;
  o.gl.memory_budget_bytes = options_.g2lf_memory_budget_bytes;
  o.gl.accumulation_budget_bytes = options_.g2lf_accumulation_budget_bytes;
  o.gl.raster = raster;
  const scene::SceneKind kind = shows_voxels() ? scene::SceneKind::kVoxels : scene::SceneKind::kGaussians;
  std::unique_ptr<lightfield::GlLightFieldRenderer>& renderer = sweeping ? sweeping_ : per_view_;
  if (!renderer)
    renderer = lightfield::make_gl_renderer(o, kind, device_);
  else
    renderer->set_options(o);
  if (settings.method == Method::kG2lfDirect)  // the panel straight from the planes: no quilt
    return renderer->render_panel_into(plan_.geometry, lens_, {}, panel_);
  if (sweeping && kind == scene::SceneKind::kGaussians) return render_g2lf(*renderer, o);
  return renderer->render_quilt_into(plan_.geometry, plan_.layout, quilt_);
}

void LightFieldFrame::fill_report(const ViewerSettings& settings, const lightfield::QuiltStats& stats,
                                  FrameReport& report) {
  if (const auto interlaced = interlace_timer_.newest_ready()) report.interlace_seconds = interlaced->seconds(0, 1);
  if (shows_voxels() && settings.method == Method::kPerView) {
    // The per-view voxel path is not timed per stage; the frame time says it all.
    report.binning_seconds = report.planes_seconds = report.swizzle_seconds = report.raster_seconds = 0.0;
    report.plane_bytes = 0;
  } else if (settings.method != Method::kPerView) {
    report.binning_seconds = stats.seconds_binning;
    report.planes_seconds = stats.seconds_planes;
    report.swizzle_seconds = stats.seconds_swizzle;
    report.plane_bytes = stats.plane_bytes;
  } else {
    report.raster_seconds = stats.seconds_raster;
    report.plane_bytes = 0;
  }
  report.gpu_peak_bytes = gpu::gpu_bytes_peak();
  report.views = plan_.layout.views;
  report.cols = plan_.layout.cols;
  report.rows = plan_.layout.rows;
  report.view_width = plan_.geometry.base.width;
  report.view_height = plan_.geometry.base.height;
  report.view_cone_deg = glm::degrees(plan_.geometry.view_cone_rad);
}

void LightFieldFrame::render(const render::CameraSpec& camera, const ViewerSettings& settings,
                             FrameReport* report) {
  plan_ = plan_frame(calibration_, camera, settings);
  const render::QuiltLayout& layout = plan_.layout;
  const bool direct = settings.method == Method::kG2lfDirect;
  if (direct)
    quilt_ = gpu::Texture();  // none on this path
  else if (quilt_.width() != layout.width || quilt_.height() != layout.height)
    quilt_ = gpu::Texture(GL_RGBA8, layout.width, layout.height);
  if (!direct && (!interlacer_layout_ || interlacer_layout_->width != layout.width ||
      interlacer_layout_->height != layout.height || interlacer_layout_->cols != layout.cols ||
      interlacer_layout_->rows != layout.rows || interlacer_layout_->views != layout.views ||
      interlacer_layout_->aspect != layout.aspect)) {
    interlacer_ = std::make_unique<gpu::GlInterlacer>(lens_, layout);
    interlacer_layout_ = layout;
  }
  const bool timed = report != nullptr;
  const lightfield::QuiltStats stats = render_quilt(settings, timed);
  if (timed) {
    interlace_timer_.begin_frame();
    interlace_timer_.stamp(0);
  }
  if (!direct) interlacer_->interlace(quilt_, panel_);
  if (timed) {
    interlace_timer_.stamp(1);
    interlace_timer_.end_frame();
  }
  if (report) fill_report(settings, stats, *report);
}

}  // namespace lfd::viewer
