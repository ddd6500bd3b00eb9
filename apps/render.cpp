// `lfd render`: render a Gaussian scene into a light-field quilt (G2LF or per view) or one view.
//   lfd render --scene guitar.compressed.ply --out guitar.png          (G2LF, 45 views, 5x9)
//   lfd render --scene s.ply --method per-view --views 45 --cols 5 --rows 9 --size 512x512 --out q.png
//   lfd render --scene s.ply --chunks 512 --plane-scale 2 --filter bilinear --out q.png
//   lfd render --scene s.ply --calibration calibration.json --panel panel.png --out q.png
//   lfd render --scene s.ply --view 22 --out view.png
//   lfd render --scene s.ply --calibration visual.json --panel panel.png --direct
// With --calibration (visual.json or calibration.json) the display chooses the view cone (the
// measured one if present), the view count (its recommendation unless --views), the tile grid
// and the view aspect; --panel interlaces the quilt for it in the same run, or with --direct
// renders the panel straight from the sweeping planes with no quilt (interlace/direct_panel.hpp).
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "display/lens_model.hpp"
#include "gpu/gl_interlacer.hpp"
#include "interlace/interlacer.hpp"
#include "scene/scene.hpp"
#include "interlace/quilt_file_name.hpp"
#include "lightfield/render_settings.hpp"
#include "lightfield/renderer_factory.hpp"
#include "lightfield/view_plan.hpp"
#include "render/camera_json.hpp"
#include "render/quilt_layout.hpp"
#include "util/default_display.hpp"
#include "util/error.hpp"

namespace lfd::apps {
namespace {

// `lfd render`'s command line: the render settings (lightfield/render_settings.hpp, shared with
// Python's lfd.render_quilt) and what only the command has (files, the panel, the backend).
struct RenderFlags {
  lightfield::RenderSettings s;
  std::string scene_path, size_text, out, camera_path, background_text = "0,0,0";
  std::string panel_path, blend = "nearest", backend_name = "cpu";
  int view = -1;
  bool overscan = false;
  bool direct = false;  // --direct: the panel straight from the planes, no quilt
  DisplaySource display_source;
};

constexpr auto kFlags = lightfield::SettingNames::kFlags;

void add_scene_and_plane_options(CLI::App& app, RenderFlags& f) {
  app.add_option("--scene", f.scene_path,
                 "scene file: Gaussians (.ply, compressed .ply, .splat, .spz) or sparse voxels (.voxels, "
                 "svraster-webgl .ply)")->required();
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
  app.add_option("--filter", f.s.filter, "G2LF and V2LF: plane sampling, nearest or bilinear")
      ->check(CLI::IsMember({"nearest", "bilinear"}))->capture_default_str();
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

void add_camera_display_and_output_options(CLI::App& app, RenderFlags& f) {
  auto* camera_opt = app.add_option("--camera", f.camera_path, "cam.json with position, look_at, up, fov_y_deg");
  app.add_option("--orbit", f.s.orbit_deg, "turn the default camera about the scene centre (degrees)")
      ->excludes(camera_opt);
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
  app.add_option("--panel", f.panel_path,
                 "also write the quilt interlaced for the --calibration (or --device) display (PNG)");
  app.add_option("--blend", f.blend, "--panel: view selection, nearest or linear")
      ->check(CLI::IsMember({"nearest", "linear"}))->capture_default_str();
  app.add_flag("--overscan", f.overscan, "--panel: fill the panel and crop instead of black bars");
  app.add_option("--background", f.background_text, "background colour R,G,B in [0, 1]")->capture_default_str();
  app.add_option("--view", f.view, "render only this view (0 = leftmost) into --out");
  add_backend_option(app, f.backend_name,
                     "cpu (the reference), gl (OpenGL 4.5 through headless EGL; exit 2 without it) or "
                     "auto (gl when a context can be made, else the CPU with a notice)");
  app.add_option("--out", f.out, "output PNG; quilts get the _qs{C}x{R}a{aspect} suffix (required unless --direct)");
  app.add_flag("--direct", f.direct,
               "G2LF and V2LF: render --panel straight from the sweeping planes, every subpixel at its own "
               "view angle, with no quilt (needs --calibration or --device and --panel; no --out)");
}

// --direct makes only the panel: the options of a quilt do not apply to it.
void check_direct_flags(const RenderFlags& f, const CLI::App& app) {
  if (!f.direct) {
    if (f.out.empty()) throw_input_error("--out: required (only --direct renders without a quilt)");
    return;
  }
  if (!f.display_source.given()) throw_input_error("--direct: needs the display (--calibration or --device)");
  if (f.panel_path.empty()) throw_input_error("--direct: needs --panel, the file it writes");
  for (const char* quilt_only : {"--out", "--view", "--cols", "--rows", "--blend"})
    if (app.count(quilt_only))
      throw_input_error("{}: a quilt option; --direct renders the panel with no quilt (every subpixel shows its own view)",
                        quilt_only);
  if (f.s.method == "per-view")
    throw_input_error("--direct: needs the sweeping planes (g2lf or v2lf), not --method per-view");
}

// What the flags ask, checked before anything is read; the texts parsed into the settings.
void check_flags(RenderFlags& f, const CLI::App& app) {
  if (!f.panel_path.empty() && !f.display_source.given())
    throw_input_error("--panel: needs the display (--calibration or --device)");
  if (f.view >= 0 && !f.panel_path.empty()) throw_input_error("--panel: needs a whole quilt; leave out --view");
  const auto bg = parse_numbers(f.background_text, ',', 3, "--background");
  if (app.count("--background")) f.s.background = glm::vec3(float(bg[0]), float(bg[1]), float(bg[2]));
  if (!f.size_text.empty()) {
    const auto wh = parse_numbers(f.size_text, 'x', 2, "--size");
    if (wh[0] < 1 || wh[1] < 1 || wh[0] > 16384 || wh[1] > 16384 || wh[0] != int(wh[0]) || wh[1] != int(wh[1]))
      throw_input_error("--size: '{}' must be two integers in [1, 16384]", f.size_text);
    f.s.size = display::ViewSize{int(wh[0]), int(wh[1])};
  }
  if (!f.camera_path.empty()) f.s.camera = render::read_camera_json(f.camera_path);
  f.s.method_given = app.count("--method") > 0;
  lightfield::check_render_settings(f.s, kFlags);
}

// The display when one is given (--calibration or --device).
struct DisplayChoice {
  std::optional<display::Calibration> calibration;
  std::string path;
};

DisplayChoice choose_display(RenderFlags& f) {
  DisplayChoice d;
  if (f.display_source.given()) {
    d.calibration = f.display_source.load();
    d.path = f.display_source.name();
  }
  return d;
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

// Interlaces the quilt as written (8 bits, and the tile aspect as its name rounds it), so the
// panel equals `lfd interlace` of the file; on the GPU when the quilt was rendered there.
void write_panel(const RenderFlags& f, const DisplayChoice& display, const Image8& quilt8,
                 const std::string& written, const render::QuiltLayout& layout, lightfield::Backend backend) {
  render::QuiltLayout as_written = layout;
  if (const auto named = render::parse_quilt_name(written)) as_written.aspect = named->aspect;
  const display::LensModel lens(display.calibration->display, display.calibration->correction);
  interlace::InterlaceOptions options;
  options.blend = interlace::parse_view_blend(f.blend);
  options.overscan = f.overscan;
  ImageF panel;
  if (backend == lightfield::Backend::kGl)
    panel = gpu::interlace_on_gpu(to_float(quilt8), as_written, lens, options);
  else
    panel = interlace::interlace(to_float(quilt8), as_written, lens, options);
  write_png(f.panel_path, to_uint8(panel));
  std::cout << fmt::format("wrote {} ({}x{} panel)\n", f.panel_path, panel.width, panel.height);
}

// --direct: the panel from the renderer's direct pass; returns the file.
std::string render_direct_panel(const RenderFlags& f, const DisplayChoice& display,
                                lightfield::LightFieldRenderer& renderer, const lightfield::ViewPlan& plan) {
  const display::LensModel lens(display.calibration->display, display.calibration->correction);
  lightfield::PanelOptions options;
  options.overscan = f.overscan;
  renderer.render_panel(plan.geometry, lens, options);
  const ImageF& panel = renderer.read_panel();
  write_png(f.panel_path, to_uint8(panel));
  std::cout << fmt::format("wrote {} ({}x{} panel, direct: no quilt)\n", f.panel_path, panel.width, panel.height);
  return f.panel_path;
}

// One view into --out, or the quilt into its suffixed name (and the panel); returns the file.
std::string render_and_write(const RenderFlags& f, const DisplayChoice& display,
                             lightfield::LightFieldRenderer& renderer, const lightfield::ViewPlan& plan) {
  if (f.view >= 0) {
    if (f.view >= plan.views) throw_input_error("--view: {} is outside 0..{}", f.view, plan.views - 1);
    write_png(f.out, to_uint8(renderer.render_view(plan.geometry, f.view)));
    return f.out;
  }
  const render::QuiltLayout& layout = plan.layout;
  const std::string written = interlace::quilt_file_name(f.out, layout);
  renderer.render_quilt(plan.geometry, layout);
  const Image8 quilt8 = to_uint8(renderer.read_quilt());
  write_png(written, quilt8);
  if (!f.panel_path.empty()) write_panel(f, display, quilt8, written, layout, renderer.options().backend);
  return written;
}

}  // namespace

int RunRender(int argc, char** argv) {
  CLI::App app{"Render a 3D Gaussian Splatting scene into a light-field quilt or a single view.\n"
               "With --calibration the display decides the view cone (measured if the file has\n"
               "it), the view count (its recommendation unless --views), the tile grid and the\n"
               "view aspect; --panel also writes the interlaced panel for that display.\n"
               "Examples:\n"
               "  lfd render --scene guitar.compressed.ply --out guitar.png\n"
               "  lfd render --scene s.ply --calibration calibration.json --panel panel.png --out q.png\n"
               "  lfd render --scene s.ply --method per-view --size 512x512 --out quilt.png\n"
               "  lfd render --scene s.ply --chunks 512 --plane-scale 2 --filter bilinear --out q.png\n"
               "  lfd render --scene s.ply --camera cam.json --calibration visual.json --out q.png\n"
               "  lfd render --scene s.ply --view 22 --out view.png",
               "render"};
  RenderFlags f;
  add_scene_and_plane_options(app, f);
  add_camera_display_and_output_options(app, f);
  if (auto code = parse(app, argc, argv)) return *code;

  check_direct_flags(f, app);
  check_flags(f, app);
  const DisplayChoice display = choose_display(f);
  const scene::SceneKind kind = scene::scene_kind_of_file(f.scene_path);
  const std::shared_ptr<lightfield::GlDevice> device =
      lightfield::GlDevice::adopt(open_backend(parse_backend(f.backend_name)));
  const lightfield::RendererOptions options =
      lightfield::renderer_options(f.s, kind, f.scene_path, lightfield::backend_for(device), kFlags);

  const auto t0 = std::chrono::steady_clock::now();
  const scene::Scene scene = scene::load_scene(f.scene_path);
  const lightfield::ViewPlan plan =
      lightfield::plan_render_views(f.s, display.calibration ? &*display.calibration : nullptr, scene, kFlags);
  print_display(display, plan);
  const std::unique_ptr<lightfield::LightFieldRenderer> renderer = lightfield::make_renderer(options, kind, device);
  renderer->set_scene(scene);
  const std::string written =
      f.direct ? render_direct_panel(f, display, *renderer, plan) : render_and_write(f, display, *renderer, plan);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << fmt::format("wrote {} ({} {}, {} on the {}, {} views of {}x{}, view cone {:.1f} deg) in {:.2f} s\n",
                           written, scene.size(), scene.primitives(),
                           f.view >= 0 ? fmt::format("view {}", f.view)
                           : lightfield::method_name(options.method, kind) + (f.direct ? " direct" : ""),
                           lightfield::processor_name(options.backend), f.view >= 0 ? 1 : plan.views,
                           plan.geometry.base.width, plan.geometry.base.height, plan.view_cone_deg, seconds);
  return 0;
}

}  // namespace lfd::apps
