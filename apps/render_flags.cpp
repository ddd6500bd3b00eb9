#include "apps/render_flags.hpp"

#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "apps/backend.hpp"
#include "render/camera_json.hpp"
#include "util/default_display.hpp"
#include "util/error.hpp"

namespace lfd::apps {

void add_scene_and_plane_options(CLI::App& app, RenderFlags& f) {
  app.add_option("--scene", f.scene_path,
                 "scene file: Gaussians (.ply, compressed .ply, .splat, .spz) or sparse voxels (.voxels, "
                 "svraster-webgl .ply); a moving scene: name_%04d.ply, a folder or a .txt list of frames")->required();
  app.add_option("--method", f.s.method,
                 "per-view (baseline) or g2lf (sweeping planes); v2lf for voxel scenes (the default there)")
      ->check(CLI::IsMember({"per-view", "g2lf", "v2lf"}))->capture_default_str();
  app.add_option("--views", f.s.views,
                 fmt::format("number of views (default: the calibration's recommendation, else {})",
                             kDefaultViewCount));
  auto* cols_o = app.add_option("--cols", f.s.cols, "quilt columns (default: chosen for the views)");
  auto* rows_o = app.add_option("--rows", f.s.rows, "quilt rows (default: chosen for the views)");
  cols_o->needs(rows_o);
  rows_o->needs(cols_o);
  app.add_option("--size", f.size_text,
                 "size of one view, WxH (default: cam.json's, else 512 tall at the display's "
                 "aspect, else 512x512)");
  app.add_option("--chunks", f.s.planes.chunks, "G2LF and V2LF: number of depth chunks N_chunk")->capture_default_str();
  app.add_option("--plane-scale", f.s.planes.plane_scale, "G2LF and V2LF: plane resolution scale P_s")->capture_default_str();
  app.add_option("--filter", f.s.filter,
                 "G2LF and V2LF: plane sampling, nearest or bilinear (default: nearest for the quilt's swizzle, "
                 "bilinear for --direct, which is closer to the continuous views there: docs/rendering.md)")
      ->check(CLI::IsMember({"nearest", "bilinear"}));
  app.add_option("--precision", f.s.precision,
                 "G2LF and V2LF: plane storage, u8 or f32 (RGBA8 / RGBA32F; G2LF on the GPU blends u8 planes "
                 "in RGBA16F, RGBA8 only where those exceed the memory), or f16 (RGBA16F, --backend gl only)")
      ->check(CLI::IsMember({"u8", "f16", "f32"}))->capture_default_str();
  app.add_option("--binning", f.s.binning,
                 "G2LF and V2LF: depth chunks, mixed (count quantiles + cuts uniform in disparity) or "
                 "quantile (the paper's equal counts)")
      ->check(CLI::IsMember({"mixed", "quantile"}))->capture_default_str();
  app.add_option("--shift", f.s.planes.d_shift,
                 "G2LF and V2LF: D_shift, move the reference camera back by this (scene units; default: by "
                 "D_forward, to the base camera; 0 = the paper's setting)");
  app.add_option("--split-levels", f.s.split_levels,
                 "V2LF: split a voxel whose depth extent straddles a chunk boundary into its 8 children, "
                 "up to this many levels deeper (0: never; measured: helps at 8 samples per voxel, hurts at 1, docs/voxels.md)")
      ->default_str("0");
  app.add_flag("--no-plane-lowpass", f.s.no_plane_lowpass,
               "V2LF: leave out the low-pass filter on the planes (the paper's stand-in for supersampling)");
}

void add_camera_and_display_options(CLI::App& app, RenderFlags& f, const std::string& panel_help) {
  f.camera_option = app.add_option("--camera", f.camera_path, "cam.json with position, look_at, up, fov_y_deg");
  app.add_option("--focal-distance", f.s.focal_distance,
                 "distance to the focal (zero-parallax) plane (default |look_at - position|)");
  auto* cone_opt = app.add_option("--view-cone", f.s.view_cone_deg,
                                  fmt::format("display view cone in degrees (default {}, or the calibration's)",
                                              kDefaultViewConeDeg));
  f.display_source.add(app, "--calibration",
                     "the display: visual.json or calibration.json (cone, views, grid, aspect)",
                     false);
  f.display_source.file_option->excludes(cone_opt);
  f.display_source.device_option->excludes(cone_opt);
  app.add_option("--panel", f.panel_path, panel_help);
  app.add_option("--blend", f.blend, "--panel: view selection, nearest or linear")
      ->check(CLI::IsMember({"nearest", "linear"}))->capture_default_str();
  app.add_flag("--overscan", f.overscan, "--panel: fill the panel and crop instead of black bars");
  app.add_option("--background", f.background_text, "background colour R,G,B in [0, 1]")->capture_default_str();
  add_backend_option(app, f.backend_name,
                     "cpu (the reference), gl (OpenGL 4.5 through headless EGL; exit 2 without it) or "
                     "auto (gl when a context can be made, else the CPU with a notice)");
  add_raster_option(app, f.s.raster);
}
void check_output_flags(RenderFlags& f, const CLI::App& app) {
  if (!f.panel_path.empty() && !f.display_source.given())
    throw_input_error("--panel: needs the display (--calibration or --device)");
  if (f.view >= 0 && !f.panel_path.empty()) throw_input_error("--panel: needs a whole quilt; leave out --view");
  const auto bg = parse_numbers(f.background_text, ',', 3, "--background");
  if (app.count("--background")) f.s.background = glm::vec3(float(bg[0]), float(bg[1]), float(bg[2]));
  if (!f.size_text.empty()) {
    f.s.size = parse_view_size(f.size_text, "--size", false);
  }
  if (!f.camera_path.empty()) f.s.camera = render::read_camera_json(f.camera_path);
  f.s.method_given = app.count("--method") > 0;
  f.s.raster_given = app.count("--raster") > 0;
  const CLI::Option* frame_option = app.get_option_no_throw("--frame");  // lfd render's only
  f.s.frame_given = frame_option && frame_option->count() > 0;
  lightfield::check_render_settings(f.s, kFlags);
  lightfield::check_backend_settings(f.s, backend_is_cpu(f.backend_name), kFlags);
}

DisplayChoice choose_display(RenderFlags& f) {
  DisplayChoice d;
  if (f.display_source.given()) {
    d.calibration = f.display_source.load();
    d.path = f.display_source.name();
  }
  return d;
}

RendererChoice choose_renderer(const RenderFlags& f, scene::SceneKind kind) {
  RendererChoice r;
  r.device = lightfield::GlDevice::adopt(open_backend(f.backend_name));
  r.options = lightfield::renderer_options(f.s, kind, f.scene_path, lightfield::backend_for(r.device), kFlags);
  if (r.device) r.options.gl.raster = resolve_raster(r.options.gl.raster, gpu::raster_subject_of(kind));
  return r;
}

void print_display(const DisplayChoice& display, const lightfield::ViewPlan& plan) {
  if (!plan.display_quilt) return;
  const render::Camera& base = plan.geometry.base;
  std::cout << fmt::format("display {}: {}\n", display.path, plan.display_quilt->describe());
  const double aspect = double(base.width) / base.height;
  if (std::abs(aspect / plan.display_quilt->view_aspect - 1.0) > 0.01)
    std::cerr << fmt::format("notice: views of {}x{} (aspect {:.4g}) on a display of aspect {:.4g}: "
                             "the interlacer fits them with black bars (leave out --size to match)\n",
                             base.width, base.height, aspect, plan.display_quilt->view_aspect);
}

}  // namespace lfd::apps
