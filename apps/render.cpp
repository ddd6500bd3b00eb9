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
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "apps/render_flags.hpp"
#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "display/lens_model.hpp"
#include "interlace/interlacer.hpp"
#include "interlace/quilt_file_name.hpp"
#include "lightfield/panel_interlacing.hpp"
#include "lightfield/render_settings.hpp"
#include "lightfield/renderer_factory.hpp"
#include "lightfield/view_plan.hpp"
#include "render/quilt_layout.hpp"
#include "scene/scene.hpp"
#include "scene/scene_sequence.hpp"
#include "util/default_display.hpp"
#include "util/error.hpp"
#include "util/stopwatch.hpp"

namespace lfd::apps {
namespace {

// --orbit, --view, --out, --direct, --frame: what `lfd render` writes.
void add_render_output_options(CLI::App& app, RenderFlags& f) {
  app.add_option("--frame", f.s.frame,
                 "a moving scene (--scene name_%04d.ply, a folder or a .txt list): render its frame K (0: the first), "
                 "framed as its first frame (as lfd record frames it)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--orbit", f.s.orbit_deg, "turn the default camera about the scene centre (degrees)")
      ->excludes(f.camera_option);
  app.add_option("--view", f.view, "render only this view (0 = leftmost) into --out");
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
  const ImageF panel = lightfield::interlace_panel(to_float(quilt8), as_written, lens, options, backend);
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
  add_camera_and_display_options(app, f, "also write the quilt interlaced for the --calibration (or --device) display (PNG)");
  add_render_output_options(app, f);
  if (auto code = parse(app, argc, argv)) return *code;

  check_direct_flags(f, app);
  check_output_flags(f, app);
  const DisplayChoice display = choose_display(f);
  const scene::SceneSequence sequence = scene::find_scene_sequence(f.scene_path);
  const std::filesystem::path& frame_file =
      lightfield::scene_frame_file(f.s, sequence, scene::is_scene_sequence(f.scene_path), kFlags);
  const scene::SceneKind kind = scene::scene_kind_of_file(sequence.frames.front());
  const RendererChoice choice = choose_renderer(f, kind);
  const lightfield::RendererOptions& options = choice.options;

  const Stopwatch stopwatch;
  // A moving scene is framed by its first frame (nothing jumps as it plays), and shows frame K.
  const scene::Scene first = scene::load_scene(sequence.frames.front());
  const scene::Scene scene = f.s.frame == 0 ? first : scene::load_scene(frame_file);
  const lightfield::ViewPlan plan =
      lightfield::plan_render_views(f.s, display.calibration ? &*display.calibration : nullptr, first, kFlags);
  print_display(display, plan);
  const std::unique_ptr<lightfield::LightFieldRenderer> renderer = lightfield::make_renderer(options, kind, choice.device);
  renderer->set_scene(scene);
  const std::string written =
      f.direct ? render_direct_panel(f, display, *renderer, plan) : render_and_write(f, display, *renderer, plan);
  const double seconds = stopwatch.seconds();
  std::cout << fmt::format("wrote {} ({} {}, {} on the {}, {} views of {}x{}, view cone {:.1f} deg) in {:.2f} s\n",
                           written, scene.size(), scene.primitives(),
                           f.view >= 0 ? fmt::format("view {}", f.view)
                           : lightfield::method_name(options.method, kind) + (f.direct ? " direct" : ""),
                           lightfield::processor_name(options.backend), f.view >= 0 ? 1 : plan.views,
                           plan.geometry.base.width, plan.geometry.base.height, plan.view_cone_deg, seconds);
  return 0;
}

}  // namespace lfd::apps
