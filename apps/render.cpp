// `lfd render`: render a Gaussian scene into a light-field quilt (G2LF or per view) or one view.
//   lfd render --scene guitar.compressed.ply --out guitar.png          (G2LF, 45 views, 5x9)
//   lfd render --scene s.ply --method per-view --views 45 --cols 5 --rows 9 --size 512x512 --out q.png
//   lfd render --scene s.ply --chunks 512 --plane-scale 2 --filter bilinear --out q.png
//   lfd render --scene s.ply --calibration calibration.json --panel panel.png --out q.png
//   lfd render --scene s.ply --view 22 --out view.png
// With --calibration (visual.json or calibration.json) the display chooses the view cone (the
// measured one if present), the view count (its recommendation unless --views), the tile grid
// and the view aspect; --panel interlaces the quilt for it in the same run.
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
#include "gpu/gl_g2lf.hpp"
#include "gpu/gl_interlacer.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_planes.hpp"
#include "gpu/gl_scene.hpp"
#include "gpu/gl_v2lf.hpp"
#include "gpu/gl_voxel_views.hpp"
#include "interlace/interlacer.hpp"
#include "render/camera_json.hpp"
#include "render/default_camera.hpp"
#include "render/g2lf.hpp"
#include "render/per_view_quilt.hpp"
#include "render/quilt_layout.hpp"
#include "render/scene_io.hpp"
#include "util/error.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_io.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_quilt.hpp"

namespace lfd::apps {
namespace {

// Adds `_qs{C}x{R}a{aspect}` before the extension unless the name already carries a tiling,
// which must then agree with the quilt.
std::string quilt_file_name(const std::string& out, const render::QuiltLayout& q) {
  if (const auto named = render::parse_quilt_name(out)) {
    if (named->cols != q.cols || named->rows != q.rows)
      throw_input_error("--out: '{}' names a {}x{} quilt but the quilt is {}x{}", out, named->cols,
                        named->rows, q.cols, q.rows);
    return out;
  }
  const std::filesystem::path p(out);
  const std::string name = p.stem().string() + render::quilt_suffix(q.cols, q.rows, q.aspect) +
                           (p.has_extension() ? p.extension().string() : std::string(".png"));
  return (p.parent_path() / name).string();
}

// The quilt (or one view) on the GPU of the current context: the same image the CPU gives, to
// within the tolerances of tests/gpu (>= 40 dB; typically 60-85 dB).
ImageF render_on_gpu(const gpu::HeadlessContext& context, const render::GaussianScene& scene,
                     const render::QuiltGeometry& geometry, const render::QuiltLayout* layout, int view,
                     const std::string& method, const render::G2lfOptions& g2lf,
                     std::optional<gpu::PlaneFormat> plane_format, const render::RasterSettings& settings) {
  if (method == "g2lf" && layout) {
    gpu::GlG2lfOptions options;
    options.g2lf = g2lf;
    options.plane_format = plane_format;
    return gpu::render_quilt_g2lf_gl(scene, geometry, *layout, options, settings);
  }
  const gpu::GlScene gl_scene(scene, context.info());
  gpu::GlPerViewRenderer renderer(gl_scene);
  if (!layout) {
    const render::RasterImage img = renderer.render_view_image(geometry.view_camera(view), settings);
    ImageF f(img.width, img.height, 3);
    f.pixels = img.rgb;
    return f;
  }
  gpu::Texture quilt(GL_RGBA32F, layout->width, layout->height);
  renderer.render_quilt(geometry, *layout, settings, quilt);
  return gpu::read_image_top_down(quilt, 3);
}

// A voxel scene's quilt (or one view) on the GPU of the current context: the CPU's image to
// within the tolerances of tests/gpu/gl_voxel_test.cpp (>= 45 dB; measured 82-109 dB).
ImageF render_voxels_on_gpu(const voxel::VoxelScene& scene, const render::QuiltGeometry& geometry,
                            const render::QuiltLayout* layout, int view, const std::string& method,
                            const voxel::V2lfOptions& v2lf, std::optional<gpu::PlaneFormat> plane_format,
                            const voxel::VoxelRenderSettings& settings) {
  if (method == "v2lf" && layout) {
    gpu::GlV2lfOptions options;
    options.v2lf = v2lf;
    options.plane_format = plane_format;
    return gpu::render_quilt_v2lf_gl(scene, geometry, *layout, options, settings.background.value_or(scene.background));
  }
  if (!layout) {
    const render::RasterImage img = gpu::render_voxel_view_gl(scene, geometry, view, settings);
    ImageF f(img.width, img.height, 3);
    f.pixels = img.rgb;
    return f;
  }
  return gpu::render_voxel_quilt_per_view_gl(scene, geometry, *layout, settings);
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
  std::string scene_path, method = "g2lf", size_text, out, camera_path, calibration_path;
  std::string filter = "nearest", precision = "u8", binning = "mixed", background_text = "0,0,0";
  std::string panel_path, blend = "nearest", backend_name = "cpu";
  std::optional<int> views_opt, cols_opt, rows_opt;
  int view = -1;
  bool overscan = false;
  float orbit_deg = 0.0f, focal_distance = 0.0f;
  std::optional<float> view_cone_opt;
  render::G2lfOptions g2lf;
  int split_levels = 0;
  bool no_plane_lowpass = false;
  app.add_option("--scene", scene_path,
                 "scene file: Gaussians (.ply, compressed .ply, .splat, .spz) or sparse voxels (.voxels, "
                 "svraster-webgl .ply)")->required();
  app.add_option("--method", method,
                 "per-view (baseline) or g2lf (sweeping planes); v2lf for voxel scenes (the default there)")
      ->check(CLI::IsMember({"per-view", "g2lf", "v2lf"}))->capture_default_str();
  app.add_option("--views", views_opt,
                 "number of views (default: the calibration's recommendation, else 45)");
  auto* cols_o = app.add_option("--cols", cols_opt, "quilt columns (default: chosen for the views)");
  auto* rows_o = app.add_option("--rows", rows_opt, "quilt rows (default: chosen for the views)");
  cols_o->needs(rows_o);
  rows_o->needs(cols_o);
  app.add_option("--size", size_text,
                 "size of one view, WxH (default: cam.json's, else 512 tall at the display's "
                 "aspect, else 512x512)");
  app.add_option("--chunks", g2lf.chunks, "G2LF and V2LF: number of depth chunks N_chunk")->capture_default_str();
  app.add_option("--plane-scale", g2lf.plane_scale, "G2LF and V2LF: plane resolution scale P_s")->capture_default_str();
  app.add_option("--filter", filter, "G2LF and V2LF: plane sampling, nearest or bilinear")
      ->check(CLI::IsMember({"nearest", "bilinear"}))->capture_default_str();
  app.add_option("--precision", precision,
                 "G2LF and V2LF: plane storage, u8 or f32 (RGBA8 / RGBA32F), or f16 (RGBA16F, --backend gl only)")
      ->check(CLI::IsMember({"u8", "f16", "f32"}))->capture_default_str();
  app.add_option("--binning", binning,
                 "G2LF and V2LF: depth chunks, mixed (count quantiles + cuts uniform in disparity) or "
                 "quantile (the paper's equal counts)")
      ->check(CLI::IsMember({"mixed", "quantile"}))->capture_default_str();
  app.add_option("--shift", g2lf.d_shift,
                 "G2LF and V2LF: D_shift, move the reference camera back by this (scene units; default: by "
                 "D_forward, to the base camera; 0 = the paper's setting)");
  app.add_option("--split-levels", split_levels,
                 "V2LF: split a voxel whose depth extent straddles a chunk boundary into its 8 children, "
                 "up to this many levels deeper (0: never; measured: helps at 8 samples per voxel, hurts at 1, docs/voxels.md)")
      ->capture_default_str();
  app.add_flag("--no-plane-lowpass", no_plane_lowpass,
               "V2LF: leave out the low-pass filter on the planes (the paper's stand-in for supersampling)");
  auto* camera_opt = app.add_option("--camera", camera_path, "cam.json with position, look_at, up, fov_y_deg");
  app.add_option("--orbit", orbit_deg, "turn the default camera about the scene centre (degrees)")
      ->excludes(camera_opt);
  app.add_option("--focal-distance", focal_distance,
                 "distance to the focal (zero-parallax) plane (default |look_at - position|)");
  auto* cone_opt = app.add_option("--view-cone", view_cone_opt,
                                  "display view cone in degrees (default 40, or the calibration's)");
  DisplaySource display_source;
  display_source.add(app, "--calibration",
                     "the display: visual.json or calibration.json (cone, views, grid, aspect)",
                     false);
  display_source.file_option->excludes(cone_opt);
  display_source.device_option->excludes(cone_opt);
  app.add_option("--panel", panel_path,
                 "also write the quilt interlaced for the --calibration (or --device) display (PNG)");
  app.add_option("--blend", blend, "--panel: view selection, nearest or linear")
      ->check(CLI::IsMember({"nearest", "linear"}))->capture_default_str();
  app.add_flag("--overscan", overscan, "--panel: fill the panel and crop instead of black bars");
  app.add_option("--background", background_text, "background colour R,G,B in [0, 1]")->capture_default_str();
  app.add_option("--view", view, "render only this view (0 = leftmost) into --out");
  add_backend_option(app, backend_name,
                     "cpu (the reference), gl (OpenGL 4.5 through headless EGL; exit 2 without it) or "
                     "auto (gl when a context can be made, else the CPU with a notice)");
  app.add_option("--out", out, "output PNG; quilts get the _qs{C}x{R}a{aspect} suffix")->required();
  if (auto code = parse(app, argc, argv)) return *code;

  g2lf.filter = render::parse_plane_filter(filter);
  // f16 exists only as a GPU texture format; the CPU planes are u8 or f32.
  const std::optional<gpu::PlaneFormat> plane_format =
      precision == "f16" ? std::optional(gpu::PlaneFormat::kRgba16f) : std::nullopt;
  g2lf.precision = render::parse_plane_precision(precision == "f16" ? "f32" : precision);
  g2lf.binning = render::parse_chunk_binning(binning);
  g2lf.check();
  if (!panel_path.empty() && !display_source.given())
    throw_input_error("--panel: needs the display (--calibration or --device)");
  if (view >= 0 && !panel_path.empty())
    throw_input_error("--panel: needs a whole quilt; leave out --view");
  const auto bg = parse_numbers(background_text, ',', 3, "--background");
  render::RasterSettings settings;
  settings.background = glm::vec3(float(bg[0]), float(bg[1]), float(bg[2]));
  if (view_cone_opt && !(*view_cone_opt > 0.0f && *view_cone_opt < 170.0f))
    throw_input_error("--view-cone: {} must lie in (0, 170) degrees", *view_cone_opt);

  // The display decides the quilt when there is one; the user's options override it.
  std::optional<display::Calibration> calibration;
  std::optional<display::DisplayQuilt> display_quilt;
  if (display_source.given()) {
    calibration = display_source.load();
    calibration_path = display_source.name();
    display_quilt = display::quilt_for_display(*calibration, views_opt);
  }
  const int views = display_quilt ? display_quilt->views : views_opt.value_or(45);
  if (views < 1 || views > 256) throw_input_error("--views: {} is outside 1..256", views);
  const float view_cone_deg =
      display_quilt ? float(display_quilt->view_cone_deg) : view_cone_opt.value_or(40.0f);

  const bool voxels = voxel::is_voxel_scene_file(scene_path);
  if (voxels && method == "g2lf" && app.count("--method"))
    throw_input_error("--method: g2lf is for Gaussian scenes; {} is a voxel scene (per-view or v2lf)", scene_path);
  if (!voxels && method == "v2lf")
    throw_input_error("--method: v2lf is for voxel scenes; {} holds Gaussians (g2lf)", scene_path);
  if (voxels && method == "g2lf") method = "v2lf";
  if (!voxels && (app.count("--split-levels") || no_plane_lowpass))
    throw_input_error("--split-levels, --no-plane-lowpass: V2LF options for voxel scenes; {} holds Gaussians", scene_path);
  voxel::V2lfOptions v2lf;
  v2lf.planes = g2lf;
  v2lf.planes.adaptive_filter = !no_plane_lowpass;
  v2lf.split_levels = split_levels;
  const auto context = open_backend(parse_backend(backend_name));
  if (plane_format && !context)
    throw_input_error("--precision: f16 (RGBA16F planes) needs the GL backend; the CPU stores u8 or f32");
  const auto t0 = std::chrono::steady_clock::now();
  const render::GaussianScene scene = voxels ? render::GaussianScene{} : render::load_scene(scene_path);
  const voxel::VoxelScene voxel_scene = voxels ? voxel::load_voxel_scene(scene_path) : voxel::VoxelScene{};
  voxel::VoxelRenderSettings voxel_settings;
  if (app.count("--background")) voxel_settings.background = settings.background;
  const render::CameraSpec spec =
      !camera_path.empty() ? render::read_camera_json(camera_path)
      : voxels             ? voxel::frame_voxel_scene(voxel_scene, 40.0f, orbit_deg)
                           : render::frame_scene(scene, 40.0f, orbit_deg);
  std::optional<int> width, height;
  if (!size_text.empty()) {
    const auto wh = parse_numbers(size_text, 'x', 2, "--size");
    if (wh[0] < 1 || wh[1] < 1 || wh[0] > 16384 || wh[1] > 16384 || wh[0] != int(wh[0]) || wh[1] != int(wh[1]))
      throw_input_error("--size: '{}' must be two integers in [1, 16384]", size_text);
    width = int(wh[0]);
    height = int(wh[1]);
  } else if (display_quilt && !spec.width && !spec.height) {
    const display::ViewSize size = display::view_size_for_display(*display_quilt);
    width = size.width;
    height = size.height;
  }
  const render::Camera base = render::camera_from_spec(spec, width, height);
  if (focal_distance <= 0.0f) focal_distance = glm::length(spec.look_at - spec.position);
  const render::QuiltGeometry geometry =
      render::make_quilt_geometry(base, focal_distance, view_cone_deg, views);
  if (display_quilt) {
    std::cout << fmt::format("display {}: {}\n", calibration_path, display_quilt->describe());
    const double aspect = double(base.width) / base.height;
    if (std::abs(aspect / display_quilt->view_aspect - 1.0) > 0.01)
      std::cerr << fmt::format("notice: views of {}x{} (aspect {:.4g}) on a display of aspect {:.4g}: "
                               "the interlacer fits them with black bars (leave out --size to match)\n",
                               base.width, base.height, aspect, display_quilt->view_aspect);
  }

  std::string written;
  if (view >= 0) {
    if (view >= views) throw_input_error("--view: {} is outside 0..{}", view, views - 1);
    ImageF f;
    if (context && voxels) {
      f = render_voxels_on_gpu(voxel_scene, geometry, nullptr, view, method, v2lf, plane_format, voxel_settings);
    } else if (context) {
      f = render_on_gpu(*context, scene, geometry, nullptr, view, method, g2lf, plane_format, settings);
    } else {
      const render::RasterImage img = voxels ? voxel::render_voxel_view(voxel_scene, geometry, view, voxel_settings)
                                             : render::render_view(scene, geometry, view, settings);
      f = ImageF(img.width, img.height, 3);
      f.pixels = img.rgb;
    }
    written = out;
    write_png(written, to_uint8(f));
  } else {
    display::QuiltGrid grid = display_quilt ? display_quilt->grid
                                          : display::quilt_grid_for_views(views, double(base.width) / base.height);
    if (cols_opt) grid = {*cols_opt, *rows_opt};
    if (grid.cols < 1 || grid.rows < 1 || grid.cols * grid.rows < views)
      throw_input_error("--cols/--rows: {}x{} tiles cannot hold {} views", grid.cols, grid.rows, views);
    const render::QuiltLayout layout = render::make_quilt_layout(geometry, grid.cols, grid.rows);
    written = quilt_file_name(out, layout);
    const ImageF quilt =
        context && voxels ? render_voxels_on_gpu(voxel_scene, geometry, &layout, -1, method, v2lf, plane_format, voxel_settings)
        : context  ? render_on_gpu(*context, scene, geometry, &layout, -1, method, g2lf, plane_format, settings)
        : method == "v2lf"
            ? voxel::render_quilt_v2lf(voxel_scene, geometry, layout, v2lf,
                                       voxel_settings.background.value_or(voxel_scene.background))
        : voxels ? voxel::render_voxel_quilt_per_view(voxel_scene, geometry, layout, voxel_settings)
        : method == "per-view" ? render::render_quilt_per_view(scene, geometry, layout, settings)
                               : render::render_quilt_g2lf(scene, geometry, layout, g2lf, settings);
    const Image8 quilt8 = to_uint8(quilt);
    write_png(written, quilt8);
    if (!panel_path.empty()) {
      // Interlace the quilt as written (8 bits, and the tile aspect as its name rounds it), so
      // the panel equals `lfd interlace` of the file.
      render::QuiltLayout as_written = layout;
      if (const auto named = render::parse_quilt_name(written)) as_written.aspect = named->aspect;
      const display::LensModel lens(calibration->display, calibration->correction);
      interlace::InterlaceOptions options;
      options.blend = blend == "linear" ? interlace::ViewBlend::kLinear : interlace::ViewBlend::kNearest;
      options.overscan = overscan;
      const ImageF panel = context ? gpu::interlace_on_gpu(to_float(quilt8), as_written, lens, options)
                                   : interlace::interlace(to_float(quilt8), as_written, lens, options);
      write_png(panel_path, to_uint8(panel));
      std::cout << fmt::format("wrote {} ({}x{} panel)\n", panel_path, panel.width, panel.height);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << fmt::format("wrote {} ({} {}, {} on the {}, {} views of {}x{}, view cone {:.1f} deg) in {:.2f} s\n",
                           written, voxels ? voxel_scene.size() : scene.size(), voxels ? "voxels" : "Gaussians", view >= 0 ? fmt::format("view {}", view) : method,
                           context ? "GPU" : "CPU",
                           view >= 0 ? 1 : views, base.width, base.height, view_cone_deg, seconds);
  return 0;
}

}  // namespace lfd::apps
