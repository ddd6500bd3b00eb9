// lfd interlace: quilt -> panel image for one display.
#include <iostream>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "display/calibration_file.hpp"
#include "interlace/interlacer.hpp"
#include "interlace/quilt_file.hpp"
#include "lightfield/backend_choice.hpp"
#include "lightfield/panel_interlacing.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

namespace lfd::apps {

int RunInterlace(int argc, char** argv) {
  CLI::App app{"Interlace a quilt into a panel image of exactly screenW x screenH for a display.\n"
               "\nExamples:\n"
               "  lfd interlace --calibration visual.json --quilt scene_qs5x9a1.6.png --out panel.png\n"
               "  lfd interlace --calibration calibration.json --quilt q.png --cols 8 --rows 6 "
               "--blend linear --out panel.png\n"
               "  lfd interlace --device auto --quilt q_qs8x6a0.75.png --out panel.png\n"
               "  lfd interlace --backend gl --calibration visual.json --quilt q_qs5x9a1.6.png "
               "--out panel.png",
               "interlace"};
  std::string quilt_path, out_path, blend = "nearest", backend_name = "cpu";
  interlace::QuiltOverrides overrides;
  bool overscan = false, invert = false;
  DisplaySource source;
  source.add(app, "--calibration", "calibration.json or visual.json");
  app.add_option("--quilt", quilt_path, "quilt image (tiling from its _qsCxRaA name)")->required();
  app.add_option("--cols", overrides.cols, "quilt columns (overrides the name)");
  app.add_option("--rows", overrides.rows, "quilt rows (overrides the name)");
  app.add_option("--views", overrides.views, "number of views (default cols*rows)");
  app.add_option("--aspect", overrides.aspect, "aspect of one tile's content");
  app.add_option("--blend", blend, "view selection: nearest or linear")
      ->check(CLI::IsMember({"nearest", "linear"}));
  app.add_flag("--overscan", overscan, "fill the panel and crop instead of black bars");
  app.add_flag("--invert", invert, "read the views in reverse order");
  add_backend_option(app, backend_name,
                     "cpu (the reference), gl (the GLSL interlacing shader on a headless OpenGL 4.5 or "
                     "ES 3.1 context, --gl: the same panel to within 1/255, exit 2 without GL) or auto (gl when a "
                     "context can be made, else the CPU with a notice)");
  std::string gl = "auto";
  add_gl_option(app, gl);
  app.add_option("--out", out_path, "panel image to write (PNG)")->required();
  if (auto code = parse(app, argc, argv)) return *code;

  const display::Calibration cal = source.load();
  const Image8 quilt8 = read_image(quilt_path, 3);
  const render::QuiltLayout layout = interlace::resolve_quilt_layout(
      quilt_path, quilt8.width, quilt8.height, overrides,
      double(cal.display.screen_w) / cal.display.screen_h);
  const display::LensModel lens(cal.display, cal.correction);
  interlace::InterlaceOptions options;
  options.blend = interlace::parse_view_blend(blend);
  options.overscan = overscan;
  options.invert_views = invert;
  const auto gl_context = open_backend(backend_name, true, gl_request(gl));
  const ImageF panel =
      lightfield::interlace_panel(to_float(quilt8), layout, lens, options, lightfield::backend_of(gl_context.get()));
  write_png(out_path, to_uint8(panel));
  std::cout << "wrote " << out_path << " (" << panel.width << "x" << panel.height << ", "
            << layout.views << " views in " << layout.cols << "x" << layout.rows << " tiles)\n";
  return 0;
}

}  // namespace lfd::apps
